// No sphere shadows its own lit side, at any scale (issue 11): a ground sphere of radius 1e3 and
// 1e4 ("Ray Tracing in One Weekend"'s ground) at the origin and offset by 1e5, and single spheres
// of radius 1e-3 to 1e4, on every path: the fresh render, the cached light move of the
// progressive renderer and the reference path in both precisions. Expected values come from
// ray-sphere intersections computed here in double, independent of the renderers: a pixel is lit
// when its surface point sees the light (ndl > 0) and the segment to the light clears every other
// sphere; its diffuse is then kd ndl (unit light, no attenuation).
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/progressive_renderer.h"
#include "engine/renderer.h"
#include "reference/reference_renderer.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

using D3 = glm::dvec3;
using Renderer = std::function<TermImages(const Scene&)>;

// The light starts elsewhere and moves to its place: the converged frame after the move comes
// from the per-sample cache (ChangeClass::light), primary hits kept, shadow rays re-traced.
TermImages render_after_light_move(const Scene& scene) {
  ProgressiveRenderer engine;
  Scene before = scene;
  before.lights[0].position +=
      glm::vec3(0.5f) * glm::length(scene.lights[0].position - scene.camera.target);
  engine.set_scene(before);
  EXPECT_TRUE(engine.wait_converged(60000));
  engine.set_scene(scene);
  EXPECT_TRUE(engine.wait_converged(60000));
  const auto frame = engine.latest();
  EXPECT_EQ(frame->info.cause, ChangeClass::light);
  return frame->images;
}

std::vector<std::pair<std::string, Renderer>> renderers() {
  return {{"fresh", [](const Scene& s) { return render(s); }},
          {"light move (cached)", render_after_light_move},
          {"reference float", [](const Scene& s) { return render_reference<float>(s); }},
          {"reference double", [](const Scene& s) { return render_reference<double>(s); }}};
}

struct Ball {
  D3 centre;
  double radius;
};

// Nearest t > 0 of the unit ray o + t d on the ball, or -1 (double, cancellation-free form).
double hit_distance(const Ball& b, const D3& o, const D3& d) {
  const D3 oc = o - b.centre;
  const double half_b = glm::dot(oc, d);
  const double len = glm::length(oc);
  const double c = (len - b.radius) * (len + b.radius);
  const double disc = half_b * half_b - c;
  if (disc < 0) return -1;
  const double q = -(half_b + std::copysign(std::sqrt(disc), half_b));
  double t0 = q, t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  return t0 > 0 ? t0 : (t1 > 0 ? t1 : -1);
}

// Distance from c to the segment a-b.
double segment_distance(const D3& c, const D3& a, const D3& b) {
  const D3 ab = b - a;
  const double u = std::clamp(glm::dot(c - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::length(a + u * ab - c);
}

struct Counts {
  int lit = 0;     // pixels checked that the light reaches
  int zeroed = 0;  // of those, rendered with no diffuse light
  int off = 0;     // of those, diffuse off kd ndl by more than 1e-3 (relative to kd)
  std::string first;
};

// Float spacing at the scene's largest coordinate relative to radius r (ulp(1e5) = 0.0078): how
// far float positions can stray, in radii.
double float_slack(const Scene& scene, double r) {
  const double far = std::max(
      {std::abs(scene.camera.eye.x), std::abs(scene.camera.eye.y), std::abs(scene.camera.eye.z)});
  return 1.2e-7 * far / r;
}

// Checks every pixel centre whose ray meets balls[0] (the surface under test) at least 1% of the
// radius inside its silhouette, with ndl > 1e-3 and a light segment that clears balls[1..] by 3%
// of their radius (plus 4 float spacings: at 1e5 a unit ball's shadow edge moves by 3%). Diffuse
// must be kd ndl within 1e-3 (plus the normal's float error). scene.camera and the light must be
// the ones the balls were built with.
Counts count_zeroed(const Scene& scene, const std::vector<Ball>& balls, const TermImages& img) {
  const D3 eye(scene.camera.eye), target(scene.camera.target), light(scene.lights[0].position);
  const double kd = scene.materials[0].diffuse.x;
  const D3 f = glm::normalize(target - eye);
  const D3 right = glm::normalize(glm::cross(f, D3(scene.camera.up)));
  const D3 up = glm::cross(right, f);
  const double tan_half = std::tan(scene.camera.fov_y * 3.14159265358979323846 / 360.0);
  const int w = img.diffuse.width, h = img.diffuse.height;
  Counts n;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const double sx = (2.0 * (x + 0.5) / w - 1.0) * tan_half * w / h;
      const double sy = (1.0 - 2.0 * (y + 0.5) / h) * tan_half;
      const D3 d = glm::normalize(f + sx * right + sy * up);
      const Ball& ground = balls[0];
      const double t = hit_distance(ground, eye, d);
      if (t < 0) continue;
      const D3 to_centre = ground.centre - eye;
      const double miss = glm::length(to_centre - glm::dot(to_centre, d) * d);
      if (miss > 0.99 * ground.radius) continue;  // silhouette: float and double may disagree
      bool clear = true;
      for (std::size_t i = 1; i < balls.size(); ++i) {
        const double ti = hit_distance(balls[i], eye, d);
        if (ti > 0 && ti < t * 1.01) clear = false;  // an occluder in front of the ground
        if (segment_distance(eye, eye + t * d, balls[i].centre) < 1.02 * balls[i].radius) {
          clear = false;
        }
      }
      if (!clear) continue;
      const D3 p = eye + t * d;
      D3 nrm = glm::normalize(p - ground.centre);
      if (glm::dot(nrm, d) > 0) nrm = -nrm;  // seen from inside
      const double ndl = glm::dot(nrm, glm::normalize(light - p));
      if (ndl <= 1e-3) continue;
      bool shadowed = false;
      for (std::size_t i = 1; i < balls.size(); ++i) {
        const double pass = segment_distance(balls[i].centre, p, light);
        const double edge = 1.03 + 4 * float_slack(scene, balls[i].radius);
        if (pass < edge * balls[i].radius) shadowed = true;
      }
      if (shadowed) continue;
      ++n.lit;
      const float got = img.diffuse.at(x, y).x;
      if (got == 0.0f) {
        if (n.zeroed++ == 0) {
          n.first =
              std::to_string(x) + "," + std::to_string(y) + " (ndl " + std::to_string(ndl) + ")";
        }
      } else if (std::abs(got - kd * ndl) > (1e-3 + float_slack(scene, ground.radius)) * kd) {
        ++n.off;
      }
    }
  }
  return n;
}

Scene base_scene(const D3& eye, const D3& target, const D3& light) {
  Scene scene;
  scene.camera.eye = glm::vec3(eye);
  scene.camera.target = glm::vec3(target);
  scene.camera.up = {0, 1, 0};
  scene.camera.fov_y = 50;
  scene.ambient = glm::vec3(0.0f);
  test::add_material(
      scene, "grey",
      test::make_material(glm::vec3(0.0f), glm::vec3(0.5f), glm::vec3(0.0f), glm::vec3(0.0f), 1));
  scene.lights.push_back(test::make_light(glm::vec3(light)));
  scene.render.width = 96;
  scene.render.height = 72;
  return scene;
}

void expect_no_zeroed(const Scene& scene, const std::vector<Ball>& balls, const std::string& what,
                      int min_lit) {
  for (const auto& [name, render_with] : renderers()) {
    const Counts n = count_zeroed(scene, balls, render_with(scene));
    const std::string label = what + ", " + name;
    EXPECT_GE(n.lit, min_lit) << label;  // the check looked at the surface
    EXPECT_EQ(n.zeroed, 0) << label << ": " << n.zeroed << " of " << n.lit
                           << " lit pixels lost their diffuse term, first at " << n.first;
    EXPECT_EQ(n.off, 0) << label << ": diffuse off kd ndl by more than 1e-3";
  }
}

// The classic ground sphere: its top at o, a unit ball resting on it casting a shadow (so the
// shadow test is exercised, not switched off), the light 8 above.
TEST(SphereSelfShadow, GroundSphereOfRadius1e3And1e4AtOriginAndOffsetBy1e5) {
  for (double radius : {1e3, 1e4}) {
    for (double offset : {0.0, 1e5}) {
      const D3 o(offset, offset, offset);
      const Ball ground{o - D3(0, radius, 0), radius};
      const Ball ball{o + D3(0, 1, -4), 1.0};
      Scene scene = base_scene(o + D3(0, 3, 6), o + D3(0, 0, -4), o + D3(2, 8, -3));
      test::add_sphere(scene, glm::vec3(ground.centre), float(ground.radius), 0);
      test::add_sphere(scene, glm::vec3(ball.centre), float(ball.radius), 0);
      expect_no_zeroed(
          scene, {ground, ball},
          "ground radius " + std::to_string(radius) + " offset " + std::to_string(offset), 2000);
    }
  }
}

// One sphere filling most of the view, the light at 3 radii: every pixel of its lit side lit.
TEST(SphereSelfShadow, LitSideOfSpheresOfRadius1em3To1e4) {
  struct Case {
    double radius, offset;
  };
  // A 1e-3 ball at 1e5 is below float's spacing there (0.0078); 1e5 is tested from radius 1.
  for (const Case c : {Case{1e-3, 0}, Case{1, 0}, Case{1e3, 0}, Case{1e4, 0}, Case{1, 1e5},
                       Case{1e3, 1e5}, Case{1e4, 1e5}}) {
    const double r = c.radius;
    const D3 centre(c.offset, c.offset, c.offset);
    Scene scene = base_scene(centre + D3(0, 0.5, 3) * r, centre, centre + D3(2, 3, 1) * r);
    test::add_sphere(scene, glm::vec3(centre), float(r), 0);
    expect_no_zeroed(scene, {{centre, r}},
                     "radius " + std::to_string(r) + " at " + std::to_string(c.offset), 1000);
  }
}

// Inside a sphere the far wall is real: a light inside lights the wall that faces it, and a
// light outside is hidden by the wall behind every visible point.
TEST(SphereSelfShadow, InsideASphereOnlyTheFarWallShadows) {
  for (double r : {1.0, 1e3}) {
    const Ball room{D3(0), r};
    Scene scene = base_scene(D3(0, 0, 0.5) * r, D3(0, 0, -1) * r, D3(0.3, 0.4, 0) * r);
    test::add_sphere(scene, glm::vec3(room.centre), float(r), 0);
    expect_no_zeroed(scene, {room}, "light inside radius " + std::to_string(r), 3000);

    scene.lights[0].position = glm::vec3(D3(0, 3, -1) * r);
    for (const auto& [name, render_with] : renderers()) {
      const TermImages img = render_with(scene);
      float most = 0;
      for (const glm::vec3& p : img.diffuse.pixels) most = std::max(most, p.x);
      EXPECT_EQ(most, 0.0f) << name << " radius " << r << ": the wall must hide an outside light";
    }
  }
}

}  // namespace
}  // namespace gloss

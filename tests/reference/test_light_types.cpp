// Directional and spot lights (docs/spec/shading.md, "Light types") in the fast renderer and the
// double reference, against geometry worked out by hand: where a spot's cone meets a floor, that
// a directional light's shadows are parallel projections, that a headlight turns with the
// camera, and the contract's numerical edges (cutoff 0.01 degrees, exponent 1e4, light along a
// surface). Each check is also run on an image made with a planted error, and must fail there.
#include <cmath>
#include <functional>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/renderer.h"
#include "reference/reference_renderer.h"
#include "scene/camera.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

using D3 = glm::dvec3;
constexpr double kPi = 3.14159265358979323846;

// A floor (y = 0, 8 x 8, matte white) seen straight down from (0, height, 0), no ambient.
Scene floor_from_above(double height, float fov_y, int size) {
  Scene scene;
  scene.camera.eye = {0.0f, static_cast<float>(height), 0.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.up = {0.0f, 0.0f, -1.0f};
  scene.camera.fov_y = fov_y;
  scene.ambient = glm::vec3(0.0f);
  const int white = test::add_material(
      scene, "white",
      test::make_material(glm::vec3(0.0f), glm::vec3(1.0f), glm::vec3(0.0f), glm::vec3(0.0f), 1));
  test::add_quad(scene, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {-4, 0, -4}, white);
  scene.render.width = scene.render.height = size;
  scene.render.spp = 1;
  return scene;
}

// Where pixel (x, y)'s centre ray meets the floor y = 0 (camera.h's formula in double).
D3 floor_point(const Scene& scene, int x, int y) {
  const CameraBasis<double> basis =
      make_camera_basis<double>(scene.camera, scene.render.width, scene.render.height);
  const D3 dir =
      camera_direction<double>(basis, x + 0.5, y + 0.5, scene.render.width, scene.render.height);
  return basis.eye + (-basis.eye.y / dir.y) * dir;
}

Light spot_light(const glm::vec3& position, const glm::vec3& direction, float cutoff) {
  Light light;
  light.type = LightType::spot;
  light.position = position;
  light.direction = direction;
  light.cutoff = cutoff;
  return light;
}

// The contract's spot factor at floor point p, by hand in double.
double spot_by_hand(const Light& light, const D3& p) {
  const D3 l = glm::normalize(D3(light.position) - p);
  const double cos_t = glm::dot(-l, glm::normalize(D3(light.direction)));
  const double cos_cutoff = std::cos(light.cutoff * kPi / 180.0);
  const double cos_inner = std::cos(std::min(light.inner, light.cutoff) * kPi / 180.0);
  if (cos_t < cos_cutoff) return 0.0;
  double spot = light.exponent == 0.0f ? 1.0 : std::pow(cos_t, double(light.exponent));
  if (cos_inner - cos_cutoff > 1e-6) {
    const double e = std::clamp((cos_t - cos_cutoff) / (cos_inner - cos_cutoff), 0.0, 1.0);
    spot *= e * e;
  }
  return spot;
}

// The floor's diffuse under one spot (kd = Ld = 1, att = 1): ndl * spot, by hand.
double spot_diffuse_by_hand(const Light& light, const D3& p) {
  const D3 l = glm::normalize(D3(light.position) - p);
  return std::max(l.y, 0.0) * spot_by_hand(light, p);
}

struct Count {
  int checked = 0, wrong = 0;
  int dark = 0;  // of the checked pixels, those that should be unlit
};

// Pixels whose floor point is farther than `margin` (in cos_t) from the cone's edge: lit inside,
// dark outside, and inside equal to the hand value within tol.
Count check_spot_floor(const Scene& scene, const Image& diffuse, double margin, double tol) {
  const Light& light = scene.lights[0];
  const double cos_cutoff = std::cos(light.cutoff * kPi / 180.0);
  Count count;
  for (int y = 0; y < scene.render.height; ++y) {
    for (int x = 0; x < scene.render.width; ++x) {
      const D3 p = floor_point(scene, x, y);
      const D3 l = glm::normalize(D3(light.position) - p);
      const double cos_t = glm::dot(-l, glm::normalize(D3(light.direction)));
      if (std::abs(cos_t - cos_cutoff) < margin) continue;
      ++count.checked;
      const double got = diffuse.at(x, y).x;
      if (!(std::abs(got - spot_diffuse_by_hand(light, p)) <= tol)) ++count.wrong;
    }
  }
  return count;
}

TEST(LightTypes, ASpotsEdgeFallsWhereTheConeSaysOnTheFloor) {
  Scene scene = floor_from_above(10.0, 40.0f, 101);
  // Tilted, so the lit region is an ellipse and a cosine against another axis shows.
  scene.lights.push_back(spot_light({0.0f, 2.0f, 0.0f}, {0.5f, -1.0f, 0.2f}, 30.0f));
  scene.render.shadows = false;
  const TermImages fast = render(scene);
  const TermImages exact = render_reference<double>(scene);
  // The edge is hard: pixels within 2e-3 of cos(cutoff) (about one pixel) are not judged.
  const Count f = check_spot_floor(scene, fast.diffuse, 2e-3, 1e-5);
  const Count e = check_spot_floor(scene, exact.diffuse, 2e-3, 1e-6);
  EXPECT_GT(f.checked, 9000);
  EXPECT_EQ(f.wrong, 0);
  EXPECT_EQ(e.wrong, 0);
  // Some pixels are lit, some not: the cone's edge is inside the image.
  int lit = 0;
  for (const glm::vec3& c : exact.diffuse.pixels) lit += c.x > 0.0f ? 1 : 0;
  EXPECT_GT(lit, 500);
  EXPECT_LT(lit, 9000);

  // Planted error: the cone's cosine taken against the floor's normal axis (straight down)
  // instead of the spot's direction. The check must see it.
  Scene wrong_axis = scene;
  wrong_axis.lights[0].direction = {0.0f, -1.0f, 0.0f};
  const Count planted = check_spot_floor(scene, render(wrong_axis).diffuse, 2e-3, 1e-5);
  EXPECT_GT(planted.wrong, 300);
}

TEST(LightTypes, ASpotsSmoothEdgeAndExponentFollowTheContract) {
  Scene scene = floor_from_above(10.0, 40.0f, 81);
  Light light = spot_light({0.0f, 2.0f, 0.0f}, {0.2f, -1.0f, 0.0f}, 35.0f);
  light.inner = 20.0f;     // fades from 20 to 35 degrees
  light.exponent = 12.0f;  // cos_t^12 on top
  scene.lights.push_back(light);
  const TermImages fast = render(scene);
  const TermImages exact = render_reference<double>(scene);
  // A smooth edge has no jump: every pixel is judged.
  EXPECT_EQ(check_spot_floor(scene, fast.diffuse, 0.0, 1e-5).wrong, 0);
  EXPECT_EQ(check_spot_floor(scene, exact.diffuse, 0.0, 1e-7).wrong, 0);
  // Planted: the edge's clamp squared left out (linear fade) must be seen.
  Scene linear = scene;
  linear.lights[0].inner = 35.0f;
  EXPECT_GT(check_spot_floor(scene, render(linear).diffuse, 0.0, 1e-5).wrong, 100);
}

// Floor pixels in the shadow of a sphere under directional light D: the line from p along -D
// passes within the radius of a centre.
TEST(LightTypes, ADirectionalLightsShadowsAreParallel) {
  Scene scene = floor_from_above(12.0, 45.0f, 121);
  const int grey = test::add_material(
      scene, "grey",
      test::make_material(glm::vec3(0.0f), glm::vec3(0.5f), glm::vec3(0.0f), glm::vec3(0.0f), 1));
  // Two equal spheres, one low and one high: a parallel light gives both the same shadow.
  const D3 centres[2] = {D3(-2.5, 1.0, -1.5), D3(-1.0, 3.0, 0.5)};
  constexpr float kRadius = 0.8f;
  for (const D3& c : centres) test::add_sphere(scene, glm::vec3(c), kRadius, grey);
  Light sun;
  sun.type = LightType::directional;
  sun.direction = {1.0f, -1.0f, 0.6f};
  scene.lights.push_back(sun);
  const D3 towards = -glm::normalize(D3(sun.direction));

  auto check = [&](const Image& diffuse) {
    Count count;
    for (int y = 0; y < scene.render.height; ++y) {
      for (int x = 0; x < scene.render.width; ++x) {
        const D3 p = floor_point(scene, x, y);
        // Only floor pixels: not covered by a sphere in the view from above.
        bool covered = false, shadowed = false;
        double nearest = 1e9;
        for (const D3& c : centres) {
          const D3 down = glm::normalize(p - D3(scene.camera.eye));
          const D3 to_c = c - D3(scene.camera.eye);
          covered |= glm::length(to_c - glm::dot(to_c, down) * down) < kRadius + 0.05;
          const D3 pc = c - p;
          const double along = glm::dot(pc, towards);
          const double miss = glm::length(pc - along * towards);
          if (along > 0.0) {
            shadowed |= miss < kRadius;
            nearest = std::min(nearest, std::abs(miss - kRadius));
          }
        }
        // Silhouettes and shadow edges are not judged, nor what lies off the floor.
        if (covered || nearest < 0.06 || std::abs(p.x) > 3.95 || std::abs(p.z) > 3.95) continue;
        ++count.checked;
        count.dark += shadowed ? 1 : 0;
        const double lit = towards.y;  // the floor: kd = 1, n = +y
        const double want = shadowed ? 0.0 : lit;
        if (!(std::abs(diffuse.at(x, y).x - want) <= 1e-5)) ++count.wrong;
      }
    }
    return count;
  };
  const Count fast = check(render(scene).diffuse);
  const Count exact = check(render_reference<double>(scene).diffuse);
  EXPECT_GT(fast.checked, 8000);
  EXPECT_GT(fast.dark, 600);  // both shadows are on the floor
  EXPECT_EQ(fast.wrong, 0);
  EXPECT_EQ(exact.wrong, 0);
  // Planted: a point light 6 units up the same way casts spreading shadows, and the high
  // sphere's shadow grows most; the check must see it.
  Scene near = scene;
  near.lights[0].type = LightType::point;
  near.lights[0].position = glm::vec3(6.0 * towards);
  const Count planted = check(render(near).diffuse);
  EXPECT_GT(planted.wrong, 100);
}

// A headlight is fixed to the camera: orbiting the camera about a sphere at the target leaves the
// image as it was (the sphere is the same from every side).
TEST(LightTypes, TheHeadlightFollowsAnOrbit) {
  Scene scene = test::head_on_sphere_scene();
  scene.lights.clear();
  Light headlight;
  headlight.type = LightType::directional;
  headlight.follow_camera = true;
  headlight.direction = {0.0f, 0.0f, -1.0f};
  scene.lights.push_back(headlight);
  scene.render.width = scene.render.height = 61;
  const TermImages before = render(scene);
  // The centre pixel looks straight at the sphere: ndl = 1, R = V: kd + ks.
  const glm::vec3 centre = before.diffuse.at(30, 30) + before.specular.at(30, 30);
  const Material& m = scene.materials[0];
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(centre[k], m.diffuse[k] + m.specular[k], 1e-5);

  Scene orbited = scene;
  orbited.camera = orbit_camera(scene.camera, 70.0f, 25.0f);
  const TermImages after = render(orbited);
  const TermImages after_exact = render_reference<double>(orbited);
  double largest = 0.0, largest_exact = 0.0;
  for (std::size_t i = 0; i < before.total.pixels.size(); ++i) {
    largest =
        std::max(largest, double(glm::length(after.total.pixels[i] - before.total.pixels[i])));
    largest_exact = std::max(
        largest_exact, double(glm::length(after_exact.total.pixels[i] - before.total.pixels[i])));
  }
  // Silhouette pixels can differ by rounding of the orbit; the sphere's interior is the same.
  EXPECT_LT(largest, 2e-3);
  EXPECT_LT(largest_exact, 2e-3);
  // Planted: the same light fixed in the world lights the sphere from the old side.
  Scene fixed = orbited;
  fixed.lights[0].follow_camera = false;
  const TermImages wrong = render(fixed);
  double planted = 0.0;
  for (std::size_t i = 0; i < before.total.pixels.size(); ++i) {
    planted =
        std::max(planted, double(glm::length(wrong.total.pixels[i] - before.total.pixels[i])));
  }
  EXPECT_GT(planted, 0.3);
}

bool all_finite(const TermImages& images) {
  for (const Image* image :
       {&images.total, &images.emissive, &images.ambient, &images.diffuse, &images.specular}) {
    for (const glm::vec3& c : image->pixels) {
      if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) return false;
    }
  }
  return true;
}

// Cutoff 0.01 degrees: cos(cutoff) = 1 - 1.5e-8, 1 in float. A spot 1 above the floor lights a
// disc of radius tan(0.01 deg) = 1.745e-4; the camera is close enough to see it.
TEST(LightTypes, ATinyCutoffStillLightsItsDisc) {
  Scene scene = floor_from_above(0.01, 4.0f, 41);  // half-width 3.5e-4
  scene.lights.push_back(spot_light({0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.01f));
  const TermImages fast = render(scene);
  const TermImages exact = render_reference<double>(scene);
  ASSERT_TRUE(all_finite(fast));
  const Count f = check_spot_floor(scene, fast.diffuse, 1e-10, 1e-5);
  const Count e = check_spot_floor(scene, exact.diffuse, 1e-10, 1e-7);
  EXPECT_GT(f.checked, 1500);
  EXPECT_EQ(f.wrong, 0);
  EXPECT_EQ(e.wrong, 0);
  int lit = 0;
  for (const glm::vec3& c : fast.diffuse.pixels) lit += c.x > 0.0f ? 1 : 0;
  // The disc covers about pi (1.745 / 3.5)^2 / 4 of the image: 0.195 of 1681 pixels.
  EXPECT_NEAR(lit, 0.195 * 41 * 41, 40);
}

TEST(LightTypes, AnExponentOf1e4FallsOffAsTheContractSays) {
  Scene scene = floor_from_above(3.0, 10.0f, 51);
  Light light = spot_light({0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 60.0f);
  light.exponent = 1e4f;  // cos_t^1e4: half strength at 0.68 degrees
  scene.lights.push_back(light);
  const TermImages fast = render(scene);
  ASSERT_TRUE(all_finite(fast));
  EXPECT_EQ(check_spot_floor(scene, fast.diffuse, 0.0, 1e-5).wrong, 0);
  EXPECT_EQ(check_spot_floor(scene, render_reference<double>(scene).diffuse, 0.0, 1e-7).wrong, 0);
}

TEST(LightTypes, ADirectionalLightAlongTheSurfaceAddsNothingAndNoNaN) {
  for (const glm::vec3& along : {glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(1.0f, -1e-7f, 0.0f)}) {
    Scene scene = floor_from_above(5.0, 40.0f, 21);
    Light light;
    light.type = LightType::directional;
    light.direction = along;
    scene.lights.push_back(light);
    const TermImages fast = render(scene);
    const TermImages exact = render_reference<double>(scene);
    ASSERT_TRUE(all_finite(fast));
    ASSERT_TRUE(all_finite(exact));
    const double ndl = std::max(0.0, -double(along.y) / glm::length(glm::dvec3(along)));
    for (const glm::vec3& c : fast.diffuse.pixels) EXPECT_NEAR(c.x, ndl, 1e-12);
    for (const glm::vec3& c : exact.diffuse.pixels) EXPECT_NEAR(c.x, ndl, 1e-12);
  }
}

}  // namespace
}  // namespace gloss

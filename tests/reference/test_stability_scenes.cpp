// Numerical stability of whole renders (docs/spec/shading.md, "Numerical expectations"): degenerate
// and sliver triangles, coordinates up to 1e5, extreme shininess, and no shadow acne on scenes
// scaled by 1e-3 and 1e4, for the fast float renderer and the reference path in both precisions.
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/renderer.h"
#include "reference/reference_renderer.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

using Renderer = std::function<TermImages(const Scene&)>;

std::vector<std::pair<std::string, Renderer>> renderers() {
  return {{"fast float", [](const Scene& s) { return render(s); }},
          {"reference float", [](const Scene& s) { return render_reference<float>(s); }},
          {"reference double", [](const Scene& s) { return render_reference<double>(s); }}};
}

// Every channel of every term image finite and >= 0; returns the largest specular channel.
float check_finite_non_negative(const TermImages& img, const std::string& what) {
  float max_specular = 0;
  for (const Image* image :
       {&img.emissive, &img.ambient, &img.diffuse, &img.specular, &img.total}) {
    for (const glm::vec3& p : image->pixels) {
      for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(p[c]) || p[c] < 0.0f) {
          ADD_FAILURE() << what << ": channel value " << p[c];
          return max_specular;
        }
      }
    }
  }
  for (const glm::vec3& p : img.specular.pixels) max_specular = std::max({max_specular, p.x, p.y});
  return max_specular;
}

// A mesh of awkward triangles in the plane z = 0 facing the camera: an ordinary one behind the
// rest, one with a repeated vertex, one with collinear vertices, a sliver 1e-6 wide and a needle;
// smooth variant with vertex normals that cancel on the sliver.
Scene awkward_triangles(bool smooth, glm::vec3 offset) {
  Scene scene;
  scene.camera.eye = offset + glm::vec3(0, 0, 4);
  scene.camera.target = offset;
  scene.camera.fov_y = 50;
  const int m = test::add_material(
      scene, "m",
      test::make_material(glm::vec3(0.1f), glm::vec3(0.6f), glm::vec3(0.8f), glm::vec3(0.0f), 50));
  auto mesh = std::make_shared<Mesh>();
  const glm::vec3 p[] = {{-2, -2, -0.1f},    {2, -2, -0.1f},
                         {0, 2, -0.1f},  // ordinary, behind
                         {-1, 0, 0},         {-1, 0, 0},
                         {-0.5f, 1, 0},  // repeated vertex
                         {0, 0, 0},          {0.5f, 0.5f, 0},
                         {1, 1, 0},  // collinear
                         {-1, -1, 0},        {1, -1, 0},
                         {0, -1 + 1e-6f, 0},  // sliver
                         {0.2f, -0.5f, 0},   {0.2f + 1e-6f, 1.5f, 0},
                         {0.2f, 1.5f, 0}};  // needle
  for (const glm::vec3& q : p) mesh->positions.push_back(q + offset);
  for (unsigned t = 0; t < 5; ++t) mesh->triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
  if (smooth) {
    for (std::size_t i = 0; i < mesh->positions.size(); ++i) {
      mesh->normals.push_back(i % 2 == 0 ? glm::vec3(0, 0, 1) : glm::vec3(0, 0, -1));
    }
  }
  Object o;
  o.name = "awkward";
  o.type = ObjectType::mesh;
  o.material = m;
  o.mesh = mesh;
  scene.objects.push_back(o);
  scene.lights.push_back(test::make_light(offset + glm::vec3(1, 2, 3)));
  // A second light exactly on the ordinary triangle: d = 0 for the samples that land there.
  scene.lights.push_back(test::make_light(offset + glm::vec3(0, 0, -0.1f)));
  scene.render.width = 48;
  scene.render.height = 36;
  scene.render.spp = 4;
  return scene;
}

TEST(StabilityScenes, DegenerateAndSliverTrianglesRenderFiniteAtAnyScaleAndShininess) {
  for (bool smooth : {false, true}) {
    for (glm::vec3 offset : {glm::vec3(0.0f), glm::vec3(1e5f, -1e5f, 1e5f)}) {
      for (float alpha : {0.0f, 1e-8f, 1e6f}) {
        Scene scene = awkward_triangles(smooth, offset);
        scene.materials[0].shininess = alpha;
        for (const auto& [name, render_with] : renderers()) {
          const std::string what = name + (smooth ? " smooth" : " flat") + " offset " +
                                   std::to_string(offset.x) + " alpha " + std::to_string(alpha);
          const TermImages img = render_with(scene);
          check_finite_non_negative(img, what);
        }
      }
    }
  }
}

// The head-on sphere of scene_fixtures.h with ks = 0.8, Ls <= 1, att <= 1 (c0 = 1): every
// specular channel is at most 0.8 at any shininess.
TEST(StabilityScenes, ExtremeShininessStaysFiniteAndBoundedInEveryRenderer) {
  for (double alpha : {0.0, 1e-8, 1e-4, 1.0, 128.0, 1e3, 1e6}) {
    Scene scene = test::head_on_sphere_scene();
    scene.materials[0].shininess = static_cast<float>(alpha);
    scene.render.spp = 4;
    for (const auto& [name, render_with] : renderers()) {
      const float max_specular =
          check_finite_non_negative(render_with(scene), name + " alpha " + std::to_string(alpha));
      EXPECT_LE(max_specular, 0.8f * (1 + 1e-6f)) << name << " alpha " << alpha;
    }
  }
}

// A unit sphere resting on the floor y = 0 at the origin, light above and to the side, all
// scaled by s; floor kd = 0.5, nothing else, so a floor pixel's diffuse is 0.5 ndl exactly when
// lit and 0 in shadow.
Scene sphere_on_floor(double s) {
  Scene scene;
  const auto S = [s](double x, double y, double z) {
    return glm::vec3(float(x * s), float(y * s), float(z * s));
  };
  scene.camera.eye = S(0, 4, 7);
  scene.camera.target = S(0, 0.5, 0);
  scene.camera.fov_y = 45;
  scene.ambient = glm::vec3(0.0f);
  const int m = test::add_material(
      scene, "grey",
      test::make_material(glm::vec3(0.0f), glm::vec3(0.5f), glm::vec3(0.0f), glm::vec3(0.0f), 1));
  test::add_quad(scene, S(-4, 0, 4), S(4, 0, 4), S(4, 0, -4), S(-4, 0, -4), m);
  test::add_sphere(scene, S(0, 1, 0), float(s), m);
  scene.lights.push_back(test::make_light(S(1.5, 5, 0.5)));
  scene.render.width = 96;
  scene.render.height = 72;
  return scene;
}

// For each pixel centre whose ray meets the floor well inside its edges and stays clear of the
// sphere (1.02 r), the expected diffuse from geometry in double: 0.5 ndl when the segment to the
// light passes the sphere at more than 1.03 r, 0 when it passes within 0.97 r; pixels between
// (the shadow's edge) are left out. Counts the lit and shadowed pixels checked and the wrong ones.
void check_no_acne(const TermImages& img, double s, const std::string& what, int& lit,
                   int& shadowed) {
  int wrong = 0;
  std::string first_wrong;
  auto expect = [&](bool ok, int x, int y, float got, double want) {
    if (ok || wrong++ > 0) return;
    first_wrong = std::to_string(x) + "," + std::to_string(y) + ": diffuse " + std::to_string(got) +
                  ", expected " + std::to_string(want);
  };
  const int w = img.diffuse.width, h = img.diffuse.height;
  using D3 = glm::dvec3;
  const D3 eye = D3(0, 4, 7) * s, target = D3(0, 0.5, 0) * s, centre = D3(0, 1, 0) * s;
  const D3 light = D3(1.5, 5, 0.5) * s;
  const double r = s, pi = 3.14159265358979323846;
  const D3 f = glm::normalize(target - eye), right = glm::normalize(glm::cross(f, D3(0, 1, 0)));
  const D3 up = glm::cross(right, f);
  const double tan_half = std::tan(22.5 * pi / 180.0);
  // Distance from the sphere's centre to the segment a-b.
  auto segment_distance = [&](const D3& a, const D3& b) {
    const D3 ab = b - a;
    const double u = std::clamp(glm::dot(centre - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    return glm::length(a + u * ab - centre);
  };
  lit = shadowed = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const double sx = (2.0 * (x + 0.5) / w - 1.0) * tan_half * w / h;
      const double sy = (1.0 - 2.0 * (y + 0.5) / h) * tan_half;
      const D3 d = glm::normalize(f + sx * right + sy * up);
      if (d.y >= 0) continue;
      const double t = -eye.y / d.y;
      const D3 q = eye + t * d;
      if (std::abs(q.x) > 3.9 * s || std::abs(q.z) > 3.9 * s) continue;
      if (segment_distance(eye, q) < 1.02 * r) continue;  // the sphere or its silhouette
      const double pass = segment_distance(q, light);
      const float got = img.diffuse.at(x, y).x;
      if (pass > 1.03 * r) {
        const double ndl = (light.y - q.y) / glm::length(light - q);
        expect(std::abs(got - 0.5 * ndl) <= 1e-4, x, y, got, 0.5 * ndl);
        ++lit;
      } else if (pass < 0.97 * r) {
        expect(got == 0.0f, x, y, got, 0.0);
        ++shadowed;
      }
    }
  }
  EXPECT_EQ(wrong, 0) << what << ": floor pixels wrongly lit or shadowed, first at " << first_wrong;
}

TEST(StabilityScenes, NoShadowAcneOnScenesScaledBy1em3And1And1e4) {
  for (double s : {1e-3, 1.0, 1e4}) {
    const Scene scene = sphere_on_floor(s);
    for (const auto& [name, render_with] : renderers()) {
      int lit = 0, shadowed = 0;
      const std::string what = name + " scale " + std::to_string(s);
      check_no_acne(render_with(scene), s, what, lit, shadowed);
      // The check must have looked at most of the floor, lit and in shadow.
      EXPECT_GT(lit, 2000) << what;
      EXPECT_GT(shadowed, 50) << what;
    }
  }
}

}  // namespace
}  // namespace gloss

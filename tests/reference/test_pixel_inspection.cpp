// The pixel inspector (reference/pixel_inspection.h): its factors against a hand computation of
// docs/spec/shading.md, and its total against the reference renderer's pixel.
#include "reference/pixel_inspection.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "reference/reference_renderer.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

using test::add_material;
using test::add_sphere;
using test::head_on_sphere_scene;
using test::make_light;
using test::make_material;
using test::sphere_on_floor_scene;

void expect_rgb(const glm::dvec3& got, double r, double g, double b, double tol) {
  EXPECT_NEAR(got.x, r, tol);
  EXPECT_NEAR(got.y, g, tol);
  EXPECT_NEAR(got.z, b, tol);
}

// The head-on sphere (tests/support/scene_fixtures.h), centre pixel (50, 50) of 101 x 101: its
// ray is the optical axis, so p = n = v = (0, 0, 1). Light 0 at (0, 3, 5): d = 5,
// l = (0, 0.6, 0.8), ndl = 0.8, att = 1 / (1 + 0.1 * 5 + 0.01 * 25) = 1 / 1.75,
// Phong R = (0, -0.6, 0.8), c = 0.8, c^10 = 0.1073741824.
// Light 1 at (0, -5, 0), below the surface: l = (0, -5, -1) / sqrt(26), ndl = -1 / sqrt(26), so
// it adds nothing. Light 2 at (0, 0, 10) straight above, blocked by a sphere of radius 0.5 at
// (0, 0, 7.5) (behind the eye, out of view): ndl = 1, c = 1, vis = 0, adds nothing.
TEST(PixelInspection, HeadOnSphereCentreMatchesHandComputation) {
  Scene scene = head_on_sphere_scene();
  scene.lights.push_back(make_light({0, -5, 0}));
  scene.lights.push_back(make_light({0, 0, 10}));
  const int grey = add_material(
      scene, "blocker",
      make_material(glm::vec3(0.0f), glm::vec3(0.5f), glm::vec3(0.0f), glm::vec3(0.0f), 1.0f));
  add_sphere(scene, {0, 0, 7.5f}, 0.5f, grey);
  scene.render.shadows = true;
  const PixelBreakdown b = inspect_pixel(scene, 50, 50);

  ASSERT_TRUE(b.hit);
  EXPECT_EQ(b.object, 0);
  EXPECT_EQ(b.object_name, "sphere0");
  EXPECT_EQ(b.material_name, "test");
  EXPECT_EQ(b.alpha, 10.0);
  EXPECT_EQ(b.energy_factor, 1.0);
  expect_rgb(b.normal, 0, 0, 1, 1e-9);
  expect_rgb(b.view, 0, 0, 1, 1e-9);
  ASSERT_EQ(b.lights.size(), 3u);

  const double att = 1.0 / 1.75;
  const LightBreakdown& l0 = b.lights[0];
  EXPECT_NEAR(l0.distance, 5.0, 1e-9);
  EXPECT_NEAR(l0.ndl, 0.8, 1e-9);
  EXPECT_NEAR(l0.cosine, 0.8, 1e-9);
  EXPECT_NEAR(l0.cosine_power, 0.1073741824, 1e-9);
  EXPECT_NEAR(l0.attenuation, att, 1e-9);
  EXPECT_EQ(l0.visibility, 1.0);
  // kd (0.5, 0.4, 0.3), Ld 1; ks 0.8, Ls (1, 0.5, 0.25).
  expect_rgb(l0.diffuse, 0.5 * 0.8 * att, 0.4 * 0.8 * att, 0.3 * 0.8 * att, 1e-7);
  const double s = 0.8 * 0.1073741824 * att;
  expect_rgb(l0.specular, s, 0.5 * s, 0.25 * s, 1e-7);

  const LightBreakdown& l1 = b.lights[1];
  EXPECT_NEAR(l1.ndl, -1.0 / std::sqrt(26.0), 1e-7);
  EXPECT_EQ(l1.cosine, 0.0);
  EXPECT_EQ(l1.cosine_power, 0.0);
  expect_rgb(l1.diffuse, 0, 0, 0, 0.0);
  expect_rgb(l1.specular, 0, 0, 0, 0.0);

  const LightBreakdown& l2 = b.lights[2];
  EXPECT_NEAR(l2.ndl, 1.0, 1e-7);
  EXPECT_NEAR(l2.cosine, 1.0, 1e-7);
  EXPECT_EQ(l2.visibility, 0.0);
  expect_rgb(l2.diffuse, 0, 0, 0, 0.0);
  expect_rgb(l2.specular, 0, 0, 0, 0.0);

  // ke (0.01, 0, 0); ka (0.1, 0.2, 0.3) times A_scene 0.2 + La (0.1 + 0 + 0).
  expect_rgb(b.emissive, 0.01, 0, 0, 1e-9);
  expect_rgb(b.ambient, 0.1 * 0.3, 0.2 * 0.3, 0.3 * 0.3, 1e-7);
  expect_rgb(b.diffuse, 0.4 * att, 0.32 * att, 0.24 * att, 1e-7);
  expect_rgb(b.specular, s, 0.5 * s, 0.25 * s, 1e-7);
  expect_rgb(b.total, 0.01 + 0.03 + 0.4 * att + s, 0.06 + 0.32 * att + 0.5 * s,
             0.09 + 0.24 * att + 0.25 * s, 1e-7);
}

// With energy normalisation on, Phong's factor is (alpha + 2) / (2 pi) = 12 / (2 pi) at alpha 10.
TEST(PixelInspection, EnergyFactorIsTheContractsNormalisation) {
  Scene scene = head_on_sphere_scene();
  scene.render.energy_normalize = true;
  const PixelBreakdown b = inspect_pixel(scene, 50, 50);
  const double factor = 12.0 / (2.0 * 3.14159265358979323846);
  EXPECT_NEAR(b.energy_factor, factor, 1e-12);
  EXPECT_NEAR(b.lights[0].specular.x, 0.8 * 0.1073741824 / 1.75 * factor, 1e-7);
}

// A corner pixel misses the sphere: the total is the background, no object, no lights.
TEST(PixelInspection, MissIsTheBackground) {
  Scene scene = head_on_sphere_scene();
  scene.background = {0.25f, 0.5f, 0.75f};
  const PixelBreakdown b = inspect_pixel(scene, 0, 0);
  EXPECT_FALSE(b.hit);
  EXPECT_EQ(b.object, -1);
  EXPECT_TRUE(b.lights.empty());
  expect_rgb(b.total, 0.25, 0.5, 0.75, 0.0);
}

// Every pixel of a scene with a floor, shadows, a miss region and two models: the inspector's
// total, rounded to float, is render_reference<double>'s pixel at one sample, bit for bit, and
// its terms are the term images' pixels.
TEST(PixelInspection, TotalIsTheReferenceRenderersPixel) {
  for (ShadingModel model : {ShadingModel::phong, ShadingModel::blinn_phong}) {
    Scene scene = sphere_on_floor_scene();
    scene.render.model = model;
    scene.render.width = 40;
    scene.render.height = 30;
    scene.background = {0.1f, 0.2f, 0.3f};
    ReferenceOptions options;
    options.spp = 1;
    const TermImages images = render_reference<double>(scene, options);
    const PixelInspector inspector(scene);
    int hits = 0;
    for (int y = 0; y < scene.render.height; ++y) {
      for (int x = 0; x < scene.render.width; ++x) {
        const PixelBreakdown b = inspector.inspect(x, y);
        hits += b.hit ? 1 : 0;
        ASSERT_EQ(glm::vec3(b.total), images.total.at(x, y)) << x << " " << y;
        ASSERT_EQ(glm::vec3(b.specular), images.specular.at(x, y)) << x << " " << y;
        ASSERT_EQ(glm::vec3(b.diffuse), images.diffuse.at(x, y)) << x << " " << y;
      }
    }
    EXPECT_GT(hits, 0);
    EXPECT_LT(hits, scene.render.width * scene.render.height);
  }
}

TEST(PixelInspection, PixelOutsideTheRenderIsRefused) {
  const Scene scene = head_on_sphere_scene();
  const PixelInspector inspector(scene);
  EXPECT_THROW(inspector.inspect(101, 0), std::out_of_range);
  EXPECT_THROW(inspector.inspect(0, -1), std::out_of_range);
}

}  // namespace
}  // namespace gloss

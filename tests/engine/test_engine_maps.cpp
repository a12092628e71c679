// Maps in the ray tracer (docs/spec/shading.md, "Textures"), with values worked out by hand:
// a cut-out's shadow, flat normal maps (exactly flat in float; 8-bit's 128/255 tilt bounded on
// a matte material and visible on a shiny one), a receding checker converging to the 256-spp
// supersampled image, and the edits of issue 22's item 6: constants recombine without a ray, a
// swapped map or a new normal scale re-shades at the cached hits without a ray, and each
// converged frame equals the one-shot render of its scene.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "engine/change_class.h"
#include "engine/progressive_renderer.h"
#include "engine/renderer.h"
#include "support/progressive_frames.h"
#include "support/scene_fixtures.h"
#include "support/test_maps.h"

namespace gloss {
namespace {

// The floor y = -1 seen straight down from (0, 4, 0), a 1 x 1 sheet at y = 0 between it and a
// light at (1, 3, 0); the sheet's opacity map has a hole in its middle quarter. No ambient.
Scene sheet_over_floor(bool with_hole) {
  Scene scene;
  scene.camera.eye = {0, 4, 0};
  scene.camera.target = {0, -1, 0};
  scene.camera.up = {0, 0, -1};
  scene.camera.fov_y = 60;
  scene.ambient = glm::vec3(0.0f);
  const int floor = test::add_material(
      scene, "floor",
      test::make_material(glm::vec3(0), glm::vec3(0.5f), glm::vec3(0), glm::vec3(0), 1));
  const int sheet = test::add_material(
      scene, "sheet",
      test::make_material(glm::vec3(0), glm::vec3(0.2f), glm::vec3(0), glm::vec3(0), 1));
  test::add_quad(scene, {-4, -1, 4}, {4, -1, 4}, {4, -1, -4}, {-4, -1, -4}, floor);
  test::add_quad(scene, {-0.5f, 0, 0.5f}, {0.5f, 0, 0.5f}, {0.5f, 0, -0.5f}, {-0.5f, 0, -0.5f},
                 sheet);
  if (with_hole) {  // 8 x 8 texels, the middle 4 x 4 transparent: u, v in (0.25, 0.75)
    scene.materials[1].map(MapSlot::opacity) =
        test::map_of(test::texture_of(8, 8, 1,
                                      [](int i, int j) {
                                        const bool inside = i >= 2 && i < 6 && j >= 2 && j < 6;
                                        return glm::vec4(inside ? 0.0f : 1.0f);
                                      }),
                     "hole");
  }
  PointLight light = test::make_light({1, 3, 0}, glm::vec3(1.0f), glm::vec3(0.0f));
  scene.lights.push_back(light);
  scene.render.width = 61;
  scene.render.height = 61;
  scene.render.spp = 1;
  scene.render.shadows = true;
  return scene;
}

// Along the image's middle row (world z = 0), each pixel centre's ray by hand: it crosses the
// sheet's plane y = 0 at x0 = 4 tan, the floor at xf = 5 tan (tan = (2 (x + 0.5) / 61 - 1)
// tan 30 deg). The sheet is there where |x0| < 0.5 and not in the hole (|x0| < 0.25: its
// opacity's bilinear value is 0.5 at u = 0.25, texel 1's centre 0.1875 opaque, texel 2's 0.3125
// not); its diffuse is 0.2 * 3 / |light - p|. Else the floor, lit where the segment to the light
// at x = 1 crosses y = 0 (at 1 + 0.75 (xf - 1)) outside the sheet or inside its hole:
// 0.5 * 4 / |light - p|; else 0.
// Pixels within 0.01 of an edge are skipped (a hit there flips by rounding).
void expect_middle_row_by_hand(const Image& diffuse, bool hole) {
  const double tan_half = std::tan(30.0 * 3.14159265358979323846 / 180.0);
  int checked = 0, shadowed = 0, through_hole = 0;
  for (int x = 0; x < 61; ++x) {
    const double t = (2.0 * (x + 0.5) / 61.0 - 1.0) * tan_half;
    const double x0 = 4.0 * t, xf = 5.0 * t, xs = 1.0 + 0.75 * (xf - 1.0);
    const auto near_edge = [](double a) {
      return std::abs(std::abs(a) - 0.5) < 0.01 || std::abs(std::abs(a) - 0.25) < 0.01;
    };
    if (near_edge(x0) || near_edge(xs)) continue;
    const bool cut = hole && std::abs(x0) < 0.25;
    double expected;
    if (std::abs(x0) < 0.5 && !cut) {
      expected = 0.2 * 3.0 / std::sqrt((1.0 - x0) * (1.0 - x0) + 9.0);
    } else {
      const bool blocked = std::abs(xs) < 0.5 && !(hole && std::abs(xs) < 0.25);
      expected = blocked ? 0.0 : 0.5 * 4.0 / std::sqrt((1.0 - xf) * (1.0 - xf) + 16.0);
      shadowed += blocked ? 1 : 0;
      through_hole += cut ? 1 : 0;
    }
    EXPECT_NEAR(diffuse.at(x, 30).x, expected, 1e-4) << "pixel " << x << (hole ? " (hole)" : "");
    ++checked;
  }
  EXPECT_GT(checked, 50);
  EXPECT_GT(shadowed, 2);  // the sheet's shadow on the floor is seen beside the sheet (or
                           // through its hole)
  if (hole) {
    EXPECT_GT(through_hole, 5);  // the floor lit through the hole is seen through it
  }
}

TEST(EngineMaps, ACutOutIsNoSurfaceForPrimaryOrShadowRays) {
  expect_middle_row_by_hand(render(sheet_over_floor(false)).diffuse, false);
  expect_middle_row_by_hand(render(sheet_over_floor(true)).diffuse, true);
}

// A tangent-space map of one texel: texel (r, g, b) everywhere.
TextureMap constant_normal_map(float r, float g, float b) {
  return test::map_of(test::texture_of(1, 1, 4, [=](int, int) { return glm::vec4(r, g, b, 1); }),
                      "flat");
}

TEST(EngineMaps, FlatNormalMapsLeaveTheImageAsItWas) {
  Scene plain = test::sphere_on_floor_scene();
  plain.render.spp = 1;
  const TermImages before = render(plain);
  // 0.5 in float is exactly flat: 2 * 0.5 - 1 = 0.
  Scene exact = plain;
  for (Material& m : exact.materials) m.map(MapSlot::normal) = constant_normal_map(0.5f, 0.5f, 1);
  EXPECT_LE(test::max_abs_diff(render(exact).total, before.total), 1e-6);

  // 8-bit (128, 128, 255) tilts n by theta = atan(sqrt(2) / 255) = 0.005546 rad (x and y of
  // n_t are 1/255 each): on a matte material the diffuse term moves by at most
  // kd Ld theta = 0.6 * 1 * 0.005546 = 0.0033 < 1/255.
  Scene matte = plain;
  for (Material& m : matte.materials) {
    m.specular = glm::vec3(0.0f);
    m.diffuse = glm::vec3(0.6f);
  }
  const TermImages matte_before = render(matte);
  for (Material& m : matte.materials) {
    m.map(MapSlot::normal) = constant_normal_map(128 / 255.0f, 128 / 255.0f, 1);
  }
  const double matte_moved = test::max_abs_diff(render(matte).total, matte_before.total);
  EXPECT_LE(matte_moved, 0.6 * std::atan(std::sqrt(2.0) / 255.0) + 1e-6);
  EXPECT_LT(matte_moved, 1.0 / 255.0);
  EXPECT_GT(matte_moved, 0.0);  // the tilt is there

  // On a shiny one (ks 1, alpha 2000) the same tilt moves the highlight by more than 1/255.
  Scene shiny = plain;
  for (Material& m : shiny.materials) {
    m.specular = glm::vec3(1.0f);
    m.shininess = 2000.0f;
  }
  const TermImages shiny_before = render(shiny);
  for (Material& m : shiny.materials) {
    m.map(MapSlot::normal) = constant_normal_map(128 / 255.0f, 128 / 255.0f, 1);
  }
  EXPECT_GT(test::max_abs_diff(render(shiny).specular, shiny_before.specular), 1.0 / 255.0);
}

// A floor of 64 x 64 checks receding to the horizon, seen at a grazing angle.
Scene receding_checker(MapFilter filter, int spp, Sampling sampling) {
  Scene scene;
  scene.camera.eye = {0, 0.6f, 4};
  scene.camera.target = {0, 0, -10};
  scene.camera.up = {0, 1, 0};
  scene.camera.fov_y = 40;
  scene.ambient = glm::vec3(1.0f);
  scene.background = glm::vec3(0.5f);
  const int floor = test::add_material(
      scene, "floor",
      test::make_material(glm::vec3(1), glm::vec3(0), glm::vec3(0), glm::vec3(0), 1));
  test::add_quad(scene, {-40, 0, 4}, {40, 0, 4}, {40, 0, -76}, {-40, 0, -76}, floor);
  scene.materials[0].map(MapSlot::diffuse) = test::map_of(test::checker(512, 8), "checker");
  scene.render.width = 64;
  scene.render.height = 40;
  scene.render.spp = spp;
  scene.render.sampling = sampling;
  scene.render.map_filter = filter;
  scene.render.shadows = false;
  return scene;
}

double mean_abs_diff(const Image& a, const Image& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) sum += std::abs(double(a.pixels[i][c]) - double(b.pixels[i][c]));
  }
  return sum / (3.0 * a.pixels.size());
}

TEST(EngineMaps, AFineCheckerAtADistanceConvergesToTheSupersampledImage) {
  // The truth: 256 stratified samples in every pixel, each at level 0 (nearest would alias).
  const Image truth = render(receding_checker(MapFilter::bilinear, 256, Sampling::uniform)).total;
  const Image trilinear =
      render(receding_checker(MapFilter::trilinear, 16, Sampling::adaptive)).total;
  const Image nearest = render(receding_checker(MapFilter::nearest, 1, Sampling::uniform)).total;
  const double tri_error = mean_abs_diff(trilinear, truth);
  const double nearest_error = mean_abs_diff(nearest, truth);
  std::printf(
      "[engine maps] receding checker against 256 spp: trilinear 16 spp adaptive %.4f, "
      "nearest 1 spp %.4f (mean absolute error)\n",
      tri_error, nearest_error);
  EXPECT_LT(tri_error, 0.01);
  EXPECT_LT(tri_error, 0.5 * nearest_error);
}

void expect_fresh(const RenderedFrame& frame, const Scene& scene) {
  RenderOptions options;
  options.placement = &frame.refined;
  const TermImages fresh = render(scene, options);
  EXPECT_LE(test::max_abs_diff(frame.images.total, fresh.total), 1e-5);
  EXPECT_LE(test::max_abs_diff(frame.images.diffuse, fresh.diffuse), 1e-5);
  EXPECT_LE(test::max_abs_diff(frame.images.specular, fresh.specular), 1e-5);
}

Scene textured_sphere_on_floor() {
  Scene scene = test::sphere_on_floor_scene();
  for (Material& m : scene.materials) {
    m.map(MapSlot::diffuse) = test::map_of(test::checker(64, 8), "checker");
    m.map(MapSlot::normal) = test::map_of(test::ripples(64, 0.5f), "ripples");
  }
  return scene;
}

TEST(EngineMaps, EditClassesOfATexturedMaterial) {
  const Scene before = textured_sphere_on_floor();
  Scene after = before;
  after.materials[0].diffuse = glm::vec3(0.1f, 0.7f, 0.2f);
  EXPECT_EQ(classify_change(before, after), ChangeClass::shade);
  after = before;
  after.materials[0].map(MapSlot::diffuse) = test::map_of(test::uv_ramp(16), "ramp");
  EXPECT_EQ(classify_change(before, after), ChangeClass::texture);
  after = before;
  after.materials[0].normal_scale = 0.25f;  // n moves: the light factors again, hits kept
  EXPECT_EQ(classify_change(before, after), ChangeClass::light);
  after = before;
  after.materials[0].map(MapSlot::opacity) = test::map_of(test::holes(32, 8), "holes");
  EXPECT_EQ(classify_change(before, after), ChangeClass::full);
}

TEST(EngineMaps, ConstantEditsRecombineAndMapEditsReShadeWithoutRays) {
  // Each edit's first image is made by its class from the cached hits; the passes after it may
  // refine the new image's edges (tracing those pixels' samples); the last one is converged.
  ProgressiveRenderer engine;
  Scene scene = textured_sphere_on_floor();
  auto frames = test::frames_of(engine, scene);
  ASSERT_FALSE(frames.empty());
  expect_fresh(*frames.back(), scene);

  scene.materials[0].diffuse = glm::vec3(0.7f, 0.2f, 0.1f);  // kd on a textured material
  frames = test::frames_of(engine, scene);
  ASSERT_FALSE(frames.empty());
  EXPECT_EQ(frames.front()->info.cause, ChangeClass::shade);
  EXPECT_EQ(frames.front()->info.rays, 0);
  expect_fresh(*frames.back(), scene);

  scene.materials[0].map(MapSlot::diffuse) = test::map_of(test::uv_ramp(16), "ramp");  // a swap
  frames = test::frames_of(engine, scene);
  ASSERT_FALSE(frames.empty());
  EXPECT_EQ(frames.front()->info.cause, ChangeClass::texture);
  EXPECT_EQ(frames.front()->info.rays, 0);
  expect_fresh(*frames.back(), scene);

  // The floor's normals turn: the light factors are made again from the cached hits, with their
  // shadow rays, but no primary ray (80 x 60 pixels would be 4800 at the centres alone).
  scene.materials[1].normal_scale = 0.3f;
  frames = test::frames_of(engine, scene);
  ASSERT_FALSE(frames.empty());
  EXPECT_EQ(frames.front()->info.cause, ChangeClass::light);
  EXPECT_LT(frames.front()->info.rays, 80 * 60);
  expect_fresh(*frames.back(), scene);
}

}  // namespace
}  // namespace gloss

// The fused first pass against the two stages it replaces, bit for bit.
#include "engine/trace/single_sample_pass.h"

#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "engine/environment/environment_stage.h"
#include "engine/trace/embree_scene.h"
#include "io/scene/scene_loader.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

// Bit for bit (memcmp: -0 and +0 differ, as do NaN payloads).
template <class Buffer>
void expect_same_bits(const Buffer& a, const Buffer& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(std::memcmp(&a[i], &b[i], sizeof a[i]), 0) << what << " differs at " << i;
  }
}

// Fused (trace_single_sample) and staged (add_samples, then build_pixel_factors) on one scene.
void expect_fused_equals_staged(const Scene& scene) {
  const EmbreeScene embree(scene);
  const RenderContext ctx = make_render_context(scene, embree);
  const int w = scene.render.width, h = scene.render.height;
  SampleCache fused_cache = make_sample_cache(scene, w, h, 1);
  PixelFactors fused;
  ASSERT_TRUE(trace_single_sample(fused_cache, ctx, fused));
  SampleCache staged_cache = make_sample_cache(scene, w, h, 1);
  PixelFactors staged;
  ASSERT_TRUE(add_samples(staged_cache, ctx, 1));
  ASSERT_TRUE(build_pixel_factors(staged_cache, ctx, staged));

  ASSERT_EQ(fused.samples, 1);
  ASSERT_EQ(fused.lights, staged.lights);
  expect_same_bits(fused.material, staged.material, "material");
  expect_same_bits(fused.weight, staged.weight, "weight");
  expect_same_bits(fused.background, staged.background, "background");
  expect_same_bits(fused.diffuse, staged.diffuse, "diffuse");
  expect_same_bits(fused.specular, staged.specular, "specular");
  EXPECT_TRUE(fused.extra_pixel.empty());
  // The cache it leaves is the staged one too.
  ASSERT_EQ(fused_cache.samples(), 1);
  expect_same_bits(fused_cache.planes[0].object, staged_cache.planes[0].object, "object");
  expect_same_bits(fused_cache.planes[0].t, staged_cache.planes[0].t, "t");
  for (std::size_t li = 0; li < ctx.plan.lights.size(); ++li) {
    expect_same_bits(fused_cache.planes[0].lights[li].cos_blinn,
                     staged_cache.planes[0].lights[li].cos_blinn, "cos_blinn");
  }
  // Given a total image, the same pass writes what combine_terms makes of the factors, and
  // under an environment the sky environment_sky makes (shown or not).
  Image total(3, 2, glm::vec3(-1.0f));  // the wrong size: resized
  ASSERT_TRUE(trace_single_sample(fused_cache, ctx, fused, &total));
  ASSERT_TRUE(environment_sky(staged_cache, ctx, staged));
  TermImages combined;
  combine_terms(staged, ctx, combined, false);
  ASSERT_EQ(total.width, w);
  ASSERT_EQ(total.height, h);
  expect_same_bits(total.pixels, combined.total.pixels, "total");
  expect_same_bits(fused.sky, staged.sky, "sky");
}

// 37 x 23: neither side a multiple of the 4 x 4 packets or the 32-pixel tiles.
TEST(SingleSamplePass, EqualsTracingThenBuildingFactorsOnASphereOverAFloor) {
  Scene scene = test::sphere_on_floor_scene();
  scene.render.width = 37;
  scene.render.height = 23;
  expect_fused_equals_staged(scene);
  scene.render.model = ShadingModel::blinn_phong;
  scene.render.pow = PowMode::fast;
  expect_fused_equals_staged(scene);
  // Two lights (their terms summed in plan order), a background, an emissive floor.
  scene.background = {0.05f, 0.1f, 0.2f};
  PointLight second = test::make_light({-3, 2, 1}, {0.3f, 0.6f, 0.9f}, {0.7f, 0.2f, 0.4f});
  second.ambient = glm::vec3(0.05f);
  scene.lights.push_back(second);
  scene.materials[1].emission = {0.02f, 0.01f, 0.0f};
  expect_fused_equals_staged(scene);
  // A background of -0 and a denormal: background pixels as combine_terms makes them.
  scene.background = {-0.0f, 1e-40f, 0.5f};
  expect_fused_equals_staged(scene);
}

// The environment's fast path and its sky: the map as the background, turned, and not shown.
TEST(SingleSamplePass, EqualsTheStagesUnderAnEnvironmentAndItsSky) {
  Scene scene = test::sphere_on_floor_scene();
  scene.render.width = 37;
  scene.render.height = 23;
  scene.camera.eye = {0.0f, 3.0f, 6.0f};  // the horizon in view: sky and surfaces in packets
  auto map = std::make_shared<EnvironmentMap>();
  map->radiance = Image(64, 32);
  for (int j = 0; j < 32; ++j) {
    for (int i = 0; i < 64; ++i) {
      map->radiance.at(i, j) = glm::vec3(0.2f + i / 64.0f, 1.0f - j / 32.0f, 0.3f);
    }
  }
  map->radiance.at(40, 8) = glm::vec3(50.0f);
  scene.environment.map = map;
  scene.environment.file = "gradient";
  scene.environment.intensity = 1.7f;
  scene.render.env_samples = 0;
  expect_fused_equals_staged(scene);
  scene.environment.rotation = 33.0f;
  expect_fused_equals_staged(scene);
  scene.environment.as_background = false;
  scene.background = {0.05f, 0.1f, 0.2f};
  expect_fused_equals_staged(scene);
}

TEST(SingleSamplePass, EqualsTracingThenBuildingFactorsOnTheCornellTeapot) {
  Scene scene = load_scene(std::string(GLOSS_ASSETS_DIR) + "/scenes/cornell-teapot.json");
  scene.render.width = 150;
  scene.render.height = 90;
  expect_fused_equals_staged(scene);
}

// A light edit on a one-sample image: fused (relight_single_sample) against recomputing the
// light factors and then the pixel factors.
TEST(SingleSamplePass, RelightEqualsRecomputingLightFactorsThenBuildingFactors) {
  Scene scene = load_scene(std::string(GLOSS_ASSETS_DIR) + "/scenes/cornell-teapot.json");
  scene.render.width = 150;
  scene.render.height = 90;
  const EmbreeScene embree(scene);
  Scene moved = scene;
  moved.lights[0].position += glm::vec3(0.2f, -0.1f, 0.05f);
  moved.lights[0].attenuation = {1.0f, 0.2f, 0.1f};
  const RenderContext before = make_render_context(scene, embree);
  const RenderContext after = make_render_context(moved, embree);

  SampleCache fused_cache = make_sample_cache(scene, 150, 90, 1);
  PixelFactors fused;
  ASSERT_TRUE(trace_single_sample(fused_cache, before, fused));
  ASSERT_TRUE(relight_single_sample(fused_cache, after, fused));

  SampleCache staged_cache = make_sample_cache(scene, 150, 90, 1);
  PixelFactors staged;
  ASSERT_TRUE(add_samples(staged_cache, before, 1));
  ASSERT_TRUE(recompute_light_factors(staged_cache, after));
  ASSERT_TRUE(build_pixel_factors(staged_cache, after, staged));

  expect_same_bits(fused.material, staged.material, "material");
  expect_same_bits(fused.diffuse, staged.diffuse, "diffuse");
  expect_same_bits(fused.specular, staged.specular, "specular");
  expect_same_bits(fused_cache.planes[0].lights[0].cos_phong,
                   staged_cache.planes[0].lights[0].cos_phong, "cos_phong");
  Image total;
  ASSERT_TRUE(relight_single_sample(fused_cache, after, fused, &total));
  TermImages combined;
  combine_terms(staged, after, combined, false);
  expect_same_bits(total.pixels, combined.total.pixels, "total");
  // And the light really moved: the factors differ from the first light's.
  PixelFactors first;
  SampleCache first_cache = make_sample_cache(scene, 150, 90, 1);
  ASSERT_TRUE(trace_single_sample(first_cache, before, first));
  std::size_t changed = 0;
  for (std::size_t i = 0; i < first.diffuse.size(); ++i)
    changed += first.diffuse[i] != fused.diffuse[i];
  EXPECT_GT(changed, first.diffuse.size() / 2);
}

// Nothing to hit and no materials: every table the lanes gather from still has its entry 0.
TEST(SingleSamplePass, SceneWithoutObjectsOrMaterialsShowsTheBackground) {
  Scene scene;
  scene.background = {0.25f, 0.5f, 0.75f};
  scene.lights.push_back(test::make_light({0, 3, 5}));
  scene.render.width = 37;
  scene.render.height = 23;
  const EmbreeScene embree(scene);
  const RenderContext ctx = make_render_context(scene, embree);
  SampleCache cache = make_sample_cache(scene, 37, 23, 1);
  PixelFactors factors;
  ASSERT_TRUE(trace_single_sample(cache, ctx, factors));
  TermImages out;
  combine_terms(factors, ctx, out, true);
  for (const glm::vec3& p : out.total.pixels) {
    EXPECT_EQ(p, glm::vec3(0.25f, 0.5f, 0.75f));
  }
  for (const glm::vec3& p : out.specular.pixels) EXPECT_EQ(p, glm::vec3(0.0f));
  Image total;
  ASSERT_TRUE(trace_single_sample(cache, ctx, factors, &total));
  for (const glm::vec3& p : total.pixels) EXPECT_EQ(p, glm::vec3(0.25f, 0.5f, 0.75f));
}

}  // namespace
}  // namespace gloss

// The interactive engine: progressive passes, cached re-shading equal to fresh renders, and
// cancellation under a storm of edits.
#include "engine/progressive_renderer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <thread>

#include <gtest/gtest.h>

#include "engine/renderer.h"
#include "support/progressive_frames.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

constexpr double kWaitMs = 60000;

// A fresh render with the frame's sample placement (adaptive sampling's refined pixels).
void expect_matches_fresh_render(const RenderedFrame& frame, const Scene& scene) {
  RenderOptions options;
  options.placement = &frame.refined;
  const TermImages fresh = render(scene, options);
  EXPECT_LE(test::max_abs_diff(frame.images.total, fresh.total), 1e-6);
  EXPECT_LE(test::max_abs_diff(frame.images.emissive, fresh.emissive), 1e-6);
  EXPECT_LE(test::max_abs_diff(frame.images.ambient, fresh.ambient), 1e-6);
  EXPECT_LE(test::max_abs_diff(frame.images.diffuse, fresh.diffuse), 1e-6);
  EXPECT_LE(test::max_abs_diff(frame.images.specular, fresh.specular), 1e-6);
}

std::shared_ptr<const RenderedFrame> converge(ProgressiveRenderer& engine, const Scene& scene) {
  engine.set_scene(scene);
  EXPECT_TRUE(engine.wait_converged(kWaitMs));
  return engine.latest();
}

// The passes of one image (width, spp of each published frame) for a sampling mode.
void expect_passes(Sampling sampling, const std::vector<int>& widths,
                   const std::vector<int>& spps) {
  std::vector<FrameInfo> seen;
  std::mutex seen_mutex;
  ProgressiveRenderer engine;  // destroyed first: its worker's callback uses the two above
  engine.set_on_publish([&] {
    std::lock_guard<std::mutex> lock(seen_mutex);
    seen.push_back(engine.latest()->info);
  });
  Scene scene = test::sphere_on_floor_scene();
  scene.render.spp = 16;
  scene.render.sampling = sampling;
  const auto frame = converge(engine, scene);
  ASSERT_NE(frame, nullptr);
  EXPECT_TRUE(frame->info.converged);
  EXPECT_EQ(frame->info.spp, 16);
  expect_matches_fresh_render(*frame, scene);
  engine.set_on_publish(nullptr);
  std::lock_guard<std::mutex> lock(seen_mutex);
  ASSERT_EQ(seen.size(), widths.size());
  for (std::size_t i = 0; i < seen.size(); ++i) {
    EXPECT_EQ(seen[i].width, widths[i]) << i;
    EXPECT_EQ(seen[i].spp, spps[i]) << i;
    EXPECT_EQ(seen[i].pass, static_cast<int>(i));
  }
}

TEST(ProgressiveRenderer, UniformPassesGoCoarseToFineAndConvergeToTheOneShotImage) {
  // 1/8, 1/4, 1/2, then 1, 2, 4, 8, 16 spp at full size.
  expect_passes(Sampling::uniform, {10, 20, 40, 80, 80, 80, 80, 80}, {1, 1, 1, 1, 2, 4, 8, 16});
}

TEST(ProgressiveRenderer, AdaptivePassesRefineTheCentreImageOnceAndConvergeToTheOneShotImage) {
  // 1/8, 1/4, 1/2, the centres at full size, then the refined pixels' 16 samples.
  expect_passes(Sampling::adaptive, {10, 20, 40, 80, 80}, {1, 1, 1, 1, 16});
}

// The viewport's default: total only. Every pass, the adaptive one too, publishes its total.
TEST(ProgressiveRenderer, TotalOnlyFramesEachCarryTheirTotal) {
  std::vector<std::pair<int, int>> sizes;  // (info.width, total.width) of each frame
  std::mutex mutex;
  ProgressiveOptions options;
  options.terms = false;
  ProgressiveRenderer engine(options);  // destroyed first: its callback uses the two above
  engine.set_on_publish([&] {
    const auto frame = engine.latest();
    std::lock_guard<std::mutex> lock(mutex);
    sizes.emplace_back(frame->info.width, frame->images.total.width);
  });
  Scene scene = test::sphere_on_floor_scene();
  scene.render.spp = 16;
  const auto frame = converge(engine, scene);
  ASSERT_NE(frame, nullptr);
  engine.set_on_publish(nullptr);
  std::lock_guard<std::mutex> lock(mutex);
  ASSERT_EQ(sizes.size(), 5u);
  for (const auto& [info_width, total_width] : sizes) EXPECT_EQ(total_width, info_width);
  RenderOptions fresh_options;
  fresh_options.placement = &frame->refined;
  EXPECT_LE(test::max_abs_diff(frame->images.total, render(scene, fresh_options).total), 1e-6);
}

// The widths of the frames published for a camera change after a first convergence.
std::vector<int> widths_after_camera_change(double preview_budget_ms) {
  std::vector<int> widths;
  std::mutex mutex;
  ProgressiveOptions options;
  options.preview_budget_ms = preview_budget_ms;
  ProgressiveRenderer engine(options);  // destroyed first: its callback uses the two above
  Scene scene = test::sphere_on_floor_scene();
  converge(engine, scene);  // measures the full-resolution pass
  engine.set_on_publish([&] {
    std::lock_guard<std::mutex> lock(mutex);
    widths.push_back(engine.latest()->info.width);
  });
  scene.camera.eye = {1, 2, 4};
  converge(engine, scene);
  engine.set_on_publish(nullptr);
  std::lock_guard<std::mutex> lock(mutex);
  return widths;
}

TEST(ProgressiveRenderer, AFastFullPassSkipsTheFinerPreviews) {
  // 80 x 60 at 4 spp, adaptive: the full pass takes well under a day, never under 0 ms.
  EXPECT_EQ(widths_after_camera_change(86400e3), (std::vector<int>{10, 80, 80}));
  EXPECT_EQ(widths_after_camera_change(0.0), (std::vector<int>{10, 20, 40, 80, 80}));
}

// An edit that keeps the primary hits: its first image is made without primary rays (none at
// all for constants and exponents), and the converged one is the fresh render's, placement and
// all (the rule runs again on the new centre image: test_progressive_convergence.cpp).
void expect_cached_edit(ProgressiveRenderer& engine, const Scene& scene, ChangeClass cause) {
  const auto frames = test::frames_of(engine, scene);
  ASSERT_FALSE(frames.empty());
  const FrameInfo& first = frames.front()->info;
  EXPECT_EQ(first.cause, cause);
  if (cause == ChangeClass::light) {
    EXPECT_GT(first.rays, 0);
    EXPECT_LT(first.rays, 80LL * 60);  // primary rays alone would be one per pixel
  } else {
    EXPECT_EQ(first.rays, 0);
  }
  EXPECT_EQ(frames.back()->info.spp, 4);
  std::vector<std::uint32_t> placement;
  RenderOptions options;
  options.refined = &placement;
  render(scene, options);
  EXPECT_EQ(frames.back()->refined, placement);
  expect_matches_fresh_render(*frames.back(), scene);
}

TEST(ProgressiveRenderer, MaterialConstantEditReshadesWithoutRaysAndMatchesFreshRender) {
  ProgressiveRenderer engine;
  Scene scene = test::sphere_on_floor_scene();
  converge(engine, scene);
  scene.materials[0].diffuse = {0.9f, 0.1f, 0.1f};
  scene.materials[1].emission = {0.05f, 0.0f, 0.0f};
  scene.lights[0].specular = {0.3f, 0.6f, 0.9f};
  scene.ambient = glm::vec3(0.4f);
  expect_cached_edit(engine, scene, ChangeClass::shade);
}

TEST(ProgressiveRenderer, ShininessAndModelEditsReshadeWithoutRays) {
  ProgressiveRenderer engine;
  Scene scene = test::sphere_on_floor_scene();
  converge(engine, scene);
  scene.materials[0].shininess = 500;
  expect_cached_edit(engine, scene, ChangeClass::exponent);
  scene.render.model = ShadingModel::blinn_phong;
  expect_cached_edit(engine, scene, ChangeClass::exponent);
}

TEST(ProgressiveRenderer, LightMoveTracesOnlyShadowRays) {
  ProgressiveRenderer engine;
  Scene scene = test::sphere_on_floor_scene();
  converge(engine, scene);
  scene.lights[0].position = {-2, 3, 1};
  expect_cached_edit(engine, scene, ChangeClass::light);
}

TEST(ProgressiveRenderer, CameraEditRestartsFromTheCoarsestPass) {
  ProgressiveRenderer engine;
  Scene scene = test::sphere_on_floor_scene();
  converge(engine, scene);
  scene.camera.eye = {1, 2, 4};
  const auto frame = converge(engine, scene);
  EXPECT_EQ(frame->info.cause, ChangeClass::full);
  expect_matches_fresh_render(*frame, scene);
}

// Thousands of edits from another thread. Each edit k sets an emission-only material to k/N
// (no other term), so a frame is torn if its sphere pixels disagree, and stale if its value
// belongs to an older generation than a frame seen before it.
TEST(ProgressiveRenderer, EditStormNeverPublishesTornOrStaleFramesAndEndsOnTheLastEdit) {
  Scene scene = test::head_on_sphere_scene();
  scene.materials[0] =
      test::make_material(glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f), 1);
  scene.lights.clear();
  scene.ambient = glm::vec3(0.0f);
  scene.render.width = 64;
  scene.render.height = 48;
  scene.render.spp = 4;
  constexpr int kEdits = 3000;
  ProgressiveRenderer engine;
  std::atomic<bool> done{false};
  std::atomic<int> torn{0}, stale{0}, frames{0};
  std::thread reader([&] {
    std::uint64_t last_generation = 0;
    while (!done.load()) {
      const auto frame = engine.latest();
      if (!frame) continue;
      ++frames;
      if (frame->info.generation < last_generation) ++stale;
      last_generation = frame->info.generation;
      // The centre pixel is fully covered at every resolution; all covered pixels must agree.
      const Image& total = frame->images.total;
      const glm::vec3 centre = total.at(total.width / 2, total.height / 2);
      for (const glm::vec3& p : total.pixels)
        if (p.x != 0.0f && p != centre && p.x > centre.x) ++torn;
      // The value encodes the edit: generation g shows edit g - 1, emission (g - 1) / kEdits.
      const float expected = static_cast<float>(frame->info.generation - 1) / kEdits;
      if (frame->info.spp >= 1 && std::abs(centre.x - expected) > 1e-6f) ++stale;
    }
  });
  std::thread writer([&] {
    Scene edit = scene;
    for (int k = 0; k < kEdits; ++k) {
      // Every class of edit, mixed: shade, exponent, light and full (a camera nudge that keeps
      // the sphere over the centre pixel).
      edit.materials[0].emission = glm::vec3(static_cast<float>(k) / kEdits);
      if (k % 4 == 1) edit.materials[0].shininess = static_cast<float>(1 + k % 50);
      if (k % 4 == 2) edit.lights = {test::make_light({0, 0, 5.0f + static_cast<float>(k % 3)})};
      if (k % 4 == 3) edit.camera.eye.x = 0.01f * static_cast<float>(k % 5);
      engine.set_scene(edit);
      // Let some passes finish between edits, so publications and cancellations interleave.
      if (k % 3 == 0) std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
  });
  writer.join();
  EXPECT_TRUE(engine.wait_converged(kWaitMs));
  done.store(true);
  reader.join();
  EXPECT_EQ(torn.load(), 0);
  EXPECT_EQ(stale.load(), 0);
  EXPECT_GT(frames.load(), 0);
  const auto last = engine.latest();
  EXPECT_EQ(last->info.generation, static_cast<std::uint64_t>(kEdits));
  EXPECT_FLOAT_EQ(last->images.total.at(32, 24).x, static_cast<float>(kEdits - 1) / kEdits);
}

TEST(ProgressiveRenderer, SetSceneReturnsTheGenerationItsFramesCarry) {
  ProgressiveRenderer engine;
  Scene scene = test::sphere_on_floor_scene();
  EXPECT_EQ(engine.set_scene(scene), 1u);
  EXPECT_EQ(engine.set_scene(scene), 1u);  // nothing changed: no new generation
  scene.camera.eye = {1, 2, 4};
  EXPECT_EQ(engine.set_scene(scene), 2u);
  ASSERT_TRUE(engine.wait_converged(kWaitMs));
  EXPECT_EQ(engine.latest()->info.generation, 2u);
}

// A paused engine publishes nothing until the next set_scene(), which resumes it: with a new
// scene (a new generation) or with the same one (the image it was refining goes on).
TEST(ProgressiveRenderer, PauseStopsWorkUntilTheNextSetScene) {
  Scene scene = test::sphere_on_floor_scene();
  scene.render.spp = 256;  // uniform: 1/8, 1/4, 1/2, full, then doubling to 256
  scene.render.sampling = Sampling::uniform;
  std::atomic<int> published{0};  // before the engine: its worker's callback uses it
  ProgressiveRenderer engine;
  // Paused from the worker itself at its second publication, so it lands before convergence.
  engine.set_on_publish([&] {
    if (++published == 2) engine.pause();
  });
  engine.set_scene(scene);
  while (published.load() < 2) std::this_thread::yield();
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(published.load(), 2);
  const int paused_count = published.load();
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(published.load(), paused_count);
  EXPECT_FALSE(engine.wait_converged(0.0));
  // The same scene resumes it and it converges on the one-shot image.
  EXPECT_EQ(engine.set_scene(scene), 1u);
  ASSERT_TRUE(engine.wait_converged(kWaitMs));
  EXPECT_GT(published.load(), paused_count);
  expect_matches_fresh_render(*engine.latest(), scene);
  // Paused again and handed a new scene: that one's frames, generation 2.
  engine.pause();
  scene.camera.eye = {1, 2, 4};
  scene.render.spp = 4;
  EXPECT_EQ(engine.set_scene(scene), 2u);
  ASSERT_TRUE(engine.wait_converged(kWaitMs));
  EXPECT_EQ(engine.latest()->info.generation, 2u);
  expect_matches_fresh_render(*engine.latest(), scene);
  engine.set_on_publish(nullptr);
}

TEST(ProgressiveRenderer, DestroyingWhileRenderingDoesNotHang) {
  for (int i = 0; i < 20; ++i) {
    ProgressiveRenderer engine;
    Scene scene = test::sphere_on_floor_scene();
    scene.render.spp = 64;
    engine.set_scene(scene);
    std::this_thread::sleep_for(std::chrono::milliseconds(i % 5));
  }
  SUCCEED();
}

}  // namespace
}  // namespace gloss

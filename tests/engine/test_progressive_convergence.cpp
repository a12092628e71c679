// Converged means exact: after edits that keep the primary hits (light moves, colours,
// exponents, and undoing them), the progressive engine's converged frame is the one-shot
// render's, with adaptive sampling's refined pixels chosen again from the new centre image.
// The expected placements come from geometry worked out here in double precision (where a
// sphere's shadow falls on the floor) and from the rule's monotonicity in kd, not from the
// engine's own output.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <thread>

#include <gtest/gtest.h>

#include "engine/progressive_renderer.h"
#include "engine/renderer.h"
#include "scene/camera.h"
#include "support/progressive_frames.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

constexpr double kWaitMs = 60000;
constexpr int kW = 96, kH = 72;

// A unit sphere resting on a matte floor (y = -1), lit from straight above at (0, 4, 0): its
// shadow is a disc around the contact point. Seen from the front and above; 16 adaptive samples.
Scene shadow_scene() {
  Scene scene;
  scene.camera.eye = {0, 3, 6};
  scene.camera.target = {0, -1, 0};
  scene.camera.up = {0, 1, 0};
  scene.camera.fov_y = 45;
  scene.ambient = glm::vec3(0.1f);
  scene.background = glm::vec3(0.0f);
  const int ball = test::add_material(
      scene, "ball",
      test::make_material(glm::vec3(0.1f), glm::vec3(0.02f), glm::vec3(0.0f), glm::vec3(0.0f), 1));
  const int floor = test::add_material(
      scene, "floor",
      test::make_material(glm::vec3(0.1f), glm::vec3(0.8f), glm::vec3(0.0f), glm::vec3(0.0f), 1));
  test::add_sphere(scene, {0, 0, 0}, 1.0f, ball);
  test::add_quad(scene, {-4, -1, 4}, {4, -1, 4}, {4, -1, -4}, {-4, -1, -4}, floor);
  scene.lights.push_back(test::make_light({0, 4, 0}));
  scene.render.width = kW;
  scene.render.height = kH;
  scene.render.spp = 16;
  scene.render.sampling = Sampling::adaptive;
  return scene;
}

struct Fresh {
  TermImages images;
  std::vector<std::uint32_t> refined;
};

Fresh fresh_render(const Scene& scene, const std::vector<std::uint32_t>* placement = nullptr) {
  Fresh f;
  RenderOptions options;
  options.refined = &f.refined;
  options.placement = placement;
  f.images = render(scene, options);
  return f;
}

// The converged frame is the fresh render: the same refined pixels, images within 1e-6.
void expect_fresh(const RenderedFrame& frame, const Scene& scene) {
  const Fresh fresh = fresh_render(scene);
  EXPECT_TRUE(frame.info.converged);
  EXPECT_EQ(frame.refined, fresh.refined);
  EXPECT_LE(test::max_abs_diff(frame.images.total, fresh.images.total), 1e-6);
  if (frame.images.diffuse.width > 0) {
    EXPECT_LE(test::max_abs_diff(frame.images.diffuse, fresh.images.diffuse), 1e-6);
    EXPECT_LE(test::max_abs_diff(frame.images.ambient, fresh.images.ambient), 1e-6);
    EXPECT_LE(test::max_abs_diff(frame.images.specular, fresh.images.specular), 1e-6);
  }
}

std::vector<std::uint32_t> minus(const std::vector<std::uint32_t>& a,
                                 const std::vector<std::uint32_t>& b) {
  std::vector<std::uint32_t> out;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

// Where the pixel centres see the floor and whether that point is in the sphere's shadow, in
// double from the scene's geometry: pixels whose floor point lies within `margin` of the
// shadow's boundary are left out (float and double may differ there). -1: not floor or too
// close; 0 lit; 1 shadowed.
std::vector<int> floor_shadow(const Scene& scene, double margin) {
  const CameraBasis<double> basis = make_camera_basis<double>(scene.camera, kW, kH);
  const glm::dvec3 eye = basis.eye, light = glm::dvec3(scene.lights[0].position);
  std::vector<int> state(static_cast<std::size_t>(kW) * kH, -1);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const glm::dvec3 d = camera_direction(basis, x + 0.5, y + 0.5, kW, kH);  // the centre
      // Ray against the unit sphere at the origin: |eye + t d|^2 = 1 has a root.
      const double b = glm::dot(eye, d), c = glm::dot(eye, eye) - 1.0;
      if (b * b - c > -1e-9) continue;  // the sphere (or its silhouette): not the floor
      const double t = (-1.0 - eye.y) / d.y;
      if (t <= 0) continue;
      const glm::dvec3 p = eye + t * d;
      if (std::abs(p.x) > 3.9 || std::abs(p.z) > 3.9) continue;
      // Shadowed when the segment from p to the light passes within 1 of the sphere's centre.
      const glm::dvec3 s = light - p;
      const double u = std::clamp(glm::dot(-p, s) / glm::dot(s, s), 0.0, 1.0);
      const double distance = glm::length(p + u * s);
      if (std::abs(distance - 1.0) < margin) continue;
      state[static_cast<std::size_t>(y) * kW + x] = distance < 1.0 ? 1 : 0;
    }
  }
  return state;
}

// Floor pixels whose centre is lit where an 8-neighbour's is shadowed, or the reverse: the rule
// refines both (adaptive_refinement.h, lit state).
std::vector<std::uint32_t> shadow_edge(const Scene& scene) {
  const std::vector<int> state = floor_shadow(scene, 1e-3);
  std::vector<std::uint32_t> edge;
  for (int y = 1; y + 1 < kH; ++y) {
    for (int x = 1; x + 1 < kW; ++x) {
      const int s = state[static_cast<std::size_t>(y) * kW + x];
      if (s < 0) continue;
      bool differs = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int n = state[static_cast<std::size_t>(y + dy) * kW + x + dx];
          differs |= n >= 0 && n != s;
        }
      if (differs) edge.push_back(static_cast<std::uint32_t>(y * kW + x));
    }
  }
  return edge;
}

bool contains_all(const std::vector<std::uint32_t>& set, const std::vector<std::uint32_t>& items) {
  return std::includes(set.begin(), set.end(), items.begin(), items.end());
}

TEST(ProgressiveRendererConvergence,
     TheShadowEdgeAfterALightMoveIsRefinedAndTheFrameIsTheFreshRender) {
  ProgressiveRenderer engine;
  Scene scene = shadow_scene();
  const auto before = test::frames_of(engine, scene).back();
  expect_fresh(*before, scene);
  ASSERT_GT(shadow_edge(scene).size(), 40u);
  EXPECT_TRUE(contains_all(before->refined, shadow_edge(scene)));

  // The light 3 units to the side: the shadow's centre moves from below the contact point to
  // x = 3 - 3 * 5/4 = -0.75 (the centre's projection from the light onto y = -1), some nine
  // pixels, so most of the new edge lies where nothing was refined.
  scene.lights[0].position = {3, 4, 0};
  const auto frames = test::frames_of(engine, scene);
  const std::vector<std::uint32_t> edge = shadow_edge(scene);
  ASSERT_GT(minus(edge, before->refined).size(), 20u);
  const RenderedFrame& first = *frames.front();
  EXPECT_EQ(first.info.cause, ChangeClass::light);
  // The first image re-lights the centres from their cached hits: shadow rays only, at most one
  // per pixel, and no refined pixels (their samples are re-lit after it).
  EXPECT_GT(first.info.rays, 0);
  EXPECT_LE(first.info.rays, static_cast<long long>(kW) * kH);
  EXPECT_EQ(first.info.spp, 1);
  EXPECT_TRUE(first.refined.empty());
  EXPECT_FALSE(first.info.converged);

  const RenderedFrame& last = *frames.back();
  expect_fresh(last, scene);
  EXPECT_TRUE(contains_all(last.refined, edge));
  // Only the newly refined pixels were traced afresh.
  EXPECT_EQ(last.info.refined_traced, minus(last.refined, before->refined).size());

  // The regression this guards against: the old placement kept. Its image differs from the
  // fresh render by far more than 1e-6 at the new shadow edge, so expect_fresh fails for it.
  const Fresh kept = fresh_render(scene, &before->refined);
  EXPECT_GT(test::max_abs_diff(kept.images.total, fresh_render(scene).images.total), 0.01);
}

TEST(ProgressiveRendererConvergence, AColourEditThatMovesTheRuleIsReshadedFirstThenRefinedAgain) {
  ProgressiveOptions total_only;
  total_only.terms = false;  // the viewport's default
  ProgressiveRenderer engine(total_only);
  Scene scene = shadow_scene();
  const auto before = test::frames_of(engine, scene).back();
  expect_fresh(*before, scene);
  // The ball's kd 0.02 -> 2: every difference the diffuse term makes between neighbours grows
  // a hundredfold and nothing else changes, so every pixel refined before still is, and the
  // step and curvature tests now see the ball's shading gradient too.
  const Scene original = scene;
  scene.materials[0].diffuse = glm::vec3(2.0f);
  const auto frames = test::frames_of(engine, scene);
  ASSERT_GE(frames.size(), 2u);
  EXPECT_EQ(frames.front()->info.cause, ChangeClass::shade);
  EXPECT_EQ(frames.front()->info.rays, 0);  // the first image re-shades the cached factors
  EXPECT_FALSE(frames.front()->info.converged);
  const auto after = frames.back();
  expect_fresh(*after, scene);
  EXPECT_TRUE(contains_all(after->refined, before->refined));
  EXPECT_GT(after->refined.size(), before->refined.size() + 50);
  EXPECT_EQ(after->info.refined_traced, after->refined.size() - before->refined.size());

  // Undo, then redo: each placement comes back exactly, as a fresh render of that state.
  const auto undone = test::frames_of(engine, original).back();
  expect_fresh(*undone, original);
  EXPECT_EQ(undone->refined, before->refined);
  EXPECT_EQ(undone->info.refined_traced, 0u);  // pixels were only dropped
  const auto redone = test::frames_of(engine, scene).back();
  expect_fresh(*redone, scene);
  EXPECT_EQ(redone->refined, after->refined);
}

TEST(ProgressiveRendererConvergence, ShininessEditsMoveTheHighlightsRefinedPixels) {
  ProgressiveRenderer engine;
  Scene scene = shadow_scene();
  scene.materials[0].specular = glm::vec3(1.0f);
  scene.materials[0].shininess = 20;
  scene.lights[0].position = {2, 4, 3};
  expect_fresh(*test::frames_of(engine, scene).back(), scene);
  scene.materials[0].shininess = 400;
  const auto frames = test::frames_of(engine, scene);
  EXPECT_EQ(frames.front()->info.cause, ChangeClass::exponent);
  EXPECT_EQ(frames.front()->info.rays, 0);
  expect_fresh(*frames.back(), scene);
  scene.render.model = ShadingModel::blinn_phong;
  expect_fresh(*test::frames_of(engine, scene).back(), scene);
}

// Edits of every class, term views switched, the engine paused and resumed, all without
// waiting: whatever passes were cancelled on the way, the end is the fresh render.
TEST(ProgressiveRendererConvergence, AnySequenceOfEditsEndsOnTheFreshRender) {
  for (const bool terms : {false, true}) {
    ProgressiveOptions options;
    options.terms = terms;
    ProgressiveRenderer engine(options);
    Scene scene = shadow_scene();
    scene.materials[1].specular = glm::vec3(0.5f);
    scene.materials[1].shininess = 30;
    engine.set_scene(scene);
    for (int k = 0; k < 60; ++k) {
      switch (k % 6) {
        case 0:
          scene.lights[0].position.x = static_cast<float>(k % 7) - 3.0f;
          break;
        case 1:
          scene.materials[0].diffuse = glm::vec3(0.1f * static_cast<float>(k % 5));
          break;
        case 2:
          scene.materials[1].shininess = static_cast<float>(5 + k);
          break;
        case 3:
          engine.set_terms(k % 4 == 3);
          break;
        case 4:
          engine.pause();
          break;
        case 5:
          scene.camera.eye.x = 0.05f * static_cast<float>(k % 3);
          break;
      }
      engine.set_scene(scene);
      std::this_thread::sleep_for(std::chrono::microseconds(200 * (k % 4)));
    }
    engine.set_terms(terms);
    engine.set_scene(scene);  // resumes it if the last edit paused it
    ASSERT_TRUE(engine.wait_converged(kWaitMs));
    expect_fresh(*engine.latest(), scene);
    // A light move and its undo after convergence, with no wait between them.
    const Scene settled = scene;
    scene.lights[0].position = {-2, 4, 1};
    engine.set_scene(scene);
    expect_fresh(*test::frames_of(engine, settled).back(), settled);
  }
}

// A machine too slow to make an edit's full image within the budget: the edit's first image is
// a preview traced afresh at a fraction of the size (exactly render()'s at that size), then the
// full image from the cached hits (a re-light: shadow rays only), then the refinement.
TEST(ProgressiveRendererConvergence, ASlowFirstPassShowsAPreviewFirst) {
  ProgressiveOptions options;
  options.edit_preview_budget_ms = 1e-9;  // any measured pass is too slow
  ProgressiveRenderer engine(options);
  Scene scene = shadow_scene();
  expect_fresh(*test::frames_of(engine, scene).back(), scene);
  Scene small = scene;
  small.render.width = kW / 8;  // the budget is never met: the coarsest level
  small.render.height = kH / 8;
  small.render.spp = 1;
  for (const glm::vec3 light : {glm::vec3(3, 4, 0), glm::vec3(-3, 4, 1)}) {
    scene.lights[0].position = small.lights[0].position = light;
    const auto frames = test::frames_of(engine, scene);
    ASSERT_GE(frames.size(), 3u);
    const RenderedFrame& preview = *frames[0];
    EXPECT_EQ(preview.info.cause, ChangeClass::light);
    EXPECT_EQ(preview.info.width, kW / 8);
    EXPECT_EQ(preview.info.height, kH / 8);
    EXPECT_FALSE(preview.info.converged);
    EXPECT_LE(test::max_abs_diff(preview.images.total, render(small).total), 1e-6);
    const RenderedFrame& relit = *frames[1];  // the full size, from the cached hits
    EXPECT_EQ(relit.info.width, kW);
    EXPECT_LE(relit.info.rays, static_cast<long long>(kW) * kH);  // shadow rays only
    expect_fresh(*frames.back(), scene);
  }
  // A colour edit: its first pass is timed the first time (no preview: nothing known yet), too
  // slow for the budget, so the next one is previewed.
  for (const float kd : {0.5f, 0.7f}) {
    scene.materials[1].diffuse = small.materials[1].diffuse = glm::vec3(kd);
    const auto frames = test::frames_of(engine, scene);
    ASSERT_GE(frames.size(), 2u);
    EXPECT_EQ(frames[0]->info.cause, ChangeClass::shade);
    EXPECT_EQ(frames[0]->info.width, kd == 0.5f ? kW : kW / 8);
    if (kd == 0.7f) {
      EXPECT_LE(test::max_abs_diff(frames[0]->images.total, render(small).total), 1e-6);
    }
    expect_fresh(*frames.back(), scene);
  }
}

// Edits that arrive faster than the engine renders them: with max_publish_gap_ms 0 a first
// image in flight is never cancelled, so frames keep coming while the edits do. Before, each
// edit cancelled the pass of the one before it, and a frame got through only when the editing
// thread stalled for a whole pass (here a re-lit 1600 x 1200 image, tens of ms, against an edit
// every millisecond). No time is asserted: the storm lasts until three frames were published.
TEST(ProgressiveRendererConvergence, ContinuousEditsStillPublishFrames) {
  ProgressiveOptions options;
  options.max_publish_gap_ms = 0;
  std::atomic<int> published{0};  // before the engine: its worker's callback uses it
  ProgressiveRenderer engine(options);
  Scene scene = shadow_scene();
#if defined(__SANITIZE_THREAD__) || defined(__SANITIZE_ADDRESS__)
  // Instrumented builds trace many times slower: a smaller image re-lights as slowly.
  scene.render.width = 400;
  scene.render.height = 300;
#else
  scene.render.width = 1600;
  scene.render.height = 1200;
#endif
  scene.render.spp = 1;
  engine.set_scene(scene);
  ASSERT_TRUE(engine.wait_converged(kWaitMs));
  engine.set_on_publish([&] { ++published; });
  const auto start = std::chrono::steady_clock::now();
  int edits = 0;
  while (published.load() < 3 &&
         std::chrono::steady_clock::now() - start < std::chrono::seconds(20)) {
    scene.lights[0].position.x = 0.001f * static_cast<float>(++edits % 1000);
    engine.set_scene(scene);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  engine.set_on_publish(nullptr);
  EXPECT_GE(published.load(), 3);
  EXPECT_GT(edits, 3);
}

}  // namespace
}  // namespace gloss

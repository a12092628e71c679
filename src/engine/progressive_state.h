#pragma once
// The progressive engine's state (progressive_renderer.h), private to the engine: the inbox the
// caller's threads write under `mutex`, the published frame under `publish_mutex`, and what the
// worker alone touches (the scene its caches belong to, the caches, the adaptive placement).
// progressive_renderer.cpp holds the doors and the worker's loop, progressive_passes.cpp what one
// pass computes.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

#include "engine/adaptive/adaptive_progression.h"
#include "engine/edit_preview.h"
#include "engine/environment/environment_estimate.h"
#include "engine/frame_pool.h"
#include "engine/progressive_renderer.h"
#include "engine/render_context.h"
#include "engine/shade/pixel_factors.h"
#include "engine/trace/embree_scene.h"
#include "engine/trace/sample_cache.h"

namespace gloss {

struct ProgressiveRenderer::Impl {
  using Clock = std::chrono::steady_clock;
  static double ms_between(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
  }

  explicit Impl(ProgressiveOptions o) : options(o), terms(o.terms) {}

  ProgressiveOptions options;

  // Inbox, guarded by mutex: the newest scene handed in and what the worker should know of it.
  std::mutex mutex;
  std::condition_variable wake;
  std::shared_ptr<const Scene> last_set;  // the caller's newest scene
  std::shared_ptr<const Scene> pending;   // not yet taken by the worker
  std::uint64_t generation = 0;
  Clock::time_point changed_at;
  bool terms;
  bool stop = false;
  bool paused = false;  // pause(): no work until the next set_scene()
  std::atomic<bool> cancel{false};
  // Publication pace (continuous edits): whether the pass in flight is the first image of its
  // generation, and when the worker last published.
  bool first_in_flight = false;
  Clock::time_point published_at;

  // Published frame, guarded by publish_mutex.
  mutable std::mutex publish_mutex;
  mutable std::condition_variable published_cv;
  std::shared_ptr<const RenderedFrame> published;
  std::function<void()> on_publish;

  // Worker-only state: the scene the cache belongs to and how far the cache lags behind it.
  std::shared_ptr<const Scene> scene;
  std::unique_ptr<EmbreeScene> embree;
  RenderContext ctx;
  SampleCache cache;
  PixelFactors factors;
  EnvironmentEstimates environment;  // the environment's exact terms, pass by pass
  std::shared_ptr<FramePool> frame_pool = std::make_shared<FramePool>();
  int level = 0;                  // 0 .. preview_levels - 1: coarse passes; preview_levels: full
  double last_full_pass_ms = -1;  // the last full-resolution 1-spp pass (preview_budget_ms)
  ChangeClass dirty = ChangeClass::none;
  // factors.sky belongs to the cache's samples and the scene's map and rotation (false after an
  // edit that changes_sky, and from the start of a pass that changes the samples until it
  // completes): only then is it made again.
  bool sky_current = false;
  // The fused 1-spp pass of a light edit wrote the centres' sky over the refined pixels' (the
  // means over their samples): the next refinement makes the sky again.
  bool refined_sky_stale = false;
  int pass = 0;
  std::uint64_t worker_generation = 0;
  Clock::time_point worker_changed_at;
  ChangeClass cause = ChangeClass::full;
  bool worker_terms = true;
  AdaptiveProgression adaptive_state;  // the refined samples' placement and its currency
  EditPreview edit_preview;            // an edit's coarse first image when its full pass is slow
  // The last published total is the current scene's centre image (no refined pixels), the image
  // the adaptive rule reads.
  bool published_centres = false;
  std::size_t refined_traced = 0;  // pixels whose refined samples the pass traced afresh

  std::thread worker;

  // progressive_renderer.cpp: the worker's loop, taking edits in, publishing.
  void run();
  bool take_inbox();
  // progressive_passes.cpp: one unit of work, then a publication; false when cancelled.
  bool step();
  void start_level(int new_level);
  // edit_preview.h: the edit at 1 / 2^shift of the full size first; false when cancelled.
  bool preview_edit(int shift, Clock::time_point start);
  // Publishes frame, its images made from the current factors.
  void publish(std::shared_ptr<RenderedFrame> frame, double pass_ms, long long rays,
               bool converged);
  // Publishes frame, its images width x height at spp samples per pixel.
  void publish_frame(std::shared_ptr<RenderedFrame> frame, int width, int height, int spp,
                     double pass_ms, long long rays, bool converged);
  // spp > 1 spent adaptively: the full-resolution cache holds centres plus refined samples.
  bool adaptive() const {
    return scene->render.spp > 1 && scene->render.sampling == Sampling::adaptive;
  }
  // Samples per pixel of the images the factors make (adaptive: per refined pixel, if any).
  int factors_spp() const {
    return factors.refined_pixel.empty() ? factors.samples : cache.refined.spp;
  }
  // Every sample traced at full resolution (the environment's passes come after).
  bool samples_done() const {
    if (level != options.preview_levels) return false;
    if (!adaptive()) return cache.samples() >= scene->render.spp;
    return adaptive_state.current(cache, scene->render.spp);
  }
  bool converged_state() const {
    return dirty == ChangeClass::none && samples_done() &&
           next_environment_steps(ctx, environment) == 0;
  }
  // adaptive_progression.h's refine(), from the published centre image when there is one. Given
  // total (the frame's, when only the total is shown) and that image, also makes the total from
  // it (combine_over_centres) and sets total_done.
  bool refine(Image* total, bool& total_done);
};

}  // namespace gloss

#include "engine/progressive_renderer.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "engine/adaptive_refinement.h"
#include "engine/environment/environment_estimate.h"
#include "engine/environment/environment_stage.h"
#include "engine/frame_pool.h"
#include "engine/render_context.h"
#include "engine/render_plan.h"
#include "engine/shade/pixel_factors.h"
#include "engine/trace/embree_scene.h"
#include "engine/trace/refined_samples.h"
#include "engine/trace/sample_cache.h"
#include "engine/trace/single_sample_pass.h"
#include "engine/trace/texture_lanes.h"
#include "scene/fields/scene_diff.h"

namespace gloss {

namespace {
using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

}  // namespace

struct ProgressiveRenderer::Impl {
  explicit Impl(ProgressiveOptions o) : options(o), terms(o.terms) {}

  ProgressiveOptions options;

  // Inbox, guarded by mutex: the newest scene handed in and what the worker should know of it.
  std::mutex mutex;
  std::condition_variable wake;
  std::shared_ptr<const Scene> last_set;  // the caller's newest scene
  std::shared_ptr<const Scene> pending;   // not yet taken by the worker
  std::uint64_t generation = 0;
  Clock::time_point changed_at;
  ChangeClass pending_change = ChangeClass::none;  // accumulated since the worker last looked
  bool terms;
  bool stop = false;
  bool paused = false;  // pause(): no work until the next set_scene()
  std::atomic<bool> cancel{false};

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
  int pass = 0;
  std::uint64_t worker_generation = 0;
  Clock::time_point worker_changed_at;
  ChangeClass cause = ChangeClass::full;
  bool worker_terms = true;

  std::thread worker;

  void run();
  bool take_inbox();
  bool step();
  void start_level(int new_level);
  // Publishes frame, its images made from the current factors.
  void publish(std::shared_ptr<RenderedFrame> frame, double pass_ms, long long rays,
               bool converged);
  // spp > 1 spent adaptively: the full-resolution cache holds centres plus refined samples.
  bool adaptive() const {
    return scene->render.spp > 1 && scene->render.sampling == Sampling::adaptive;
  }
  // Samples per pixel the cache stands for (adaptive: per refined pixel, once refined).
  int cached_spp() const { return cache.refined.spp > 0 ? cache.refined.spp : cache.samples(); }
  // Every sample traced at full resolution (the environment's passes come after).
  bool samples_done() const {
    return level == options.preview_levels && cached_spp() >= scene->render.spp;
  }
  bool converged_state() const {
    return dirty == ChangeClass::none && samples_done() &&
           next_environment_steps(ctx, environment) == 0;
  }
  // Traces the refined samples the centre image asks for; false when cancelled.
  bool refine();
};

void ProgressiveRenderer::Impl::run() {
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mutex);
      wake.wait(lock, [&] {
        return stop || pending != nullptr || terms != worker_terms ||
               (!paused && scene != nullptr && !converged_state());
      });
      if (stop) return;
    }
    take_inbox();
    bool paused_now;
    {
      std::lock_guard<std::mutex> lock(mutex);
      paused_now = paused;  // a terms change while paused is taken in, not rendered
    }
    if (scene != nullptr && !paused_now) step();
  }
}

// Moves the newest scene from the inbox into the worker's state; true when one was taken.
bool ProgressiveRenderer::Impl::take_inbox() {
  std::shared_ptr<const Scene> next;
  bool want_terms;
  {
    std::lock_guard<std::mutex> lock(mutex);
    want_terms = terms;
    if (pending == nullptr && want_terms == worker_terms) return false;
    next = std::move(pending);
    pending = nullptr;
    cancel.store(false);
    if (next != nullptr) {
      worker_generation = generation;
      worker_changed_at = changed_at;
    }
  }
  if (want_terms != worker_terms) {
    worker_terms = want_terms;
    dirty = std::max(dirty, ChangeClass::shade);
  }
  if (next == nullptr) return true;
  const SceneDiff diff = scene == nullptr ? SceneDiff{} : diff_scenes(*scene, *next);
  const ChangeClass change =
      scene == nullptr ? ChangeClass::full : classify_change(*scene, *next, diff);
  cause = change;
  pass = 0;
  if (embree == nullptr || scene == nullptr || diff.geometry) {
    embree = std::make_unique<EmbreeScene>(*next);
  }
  scene = std::move(next);
  bind_scene(ctx, *scene, *embree);
  ctx.cancel = &cancel;
  dirty = std::max(dirty, change);
  return true;
}

void ProgressiveRenderer::Impl::start_level(int new_level) {
  level = new_level;
  const RenderSettings& r = scene->render;
  const int shift = options.preview_levels - level;  // 3, 2, 1 -> 1/8, 1/4, 1/2
  const int w = std::max(1, r.width >> shift), h = std::max(1, r.height >> shift);
  const int target = level == options.preview_levels && !adaptive() ? r.spp : 1;
  reset_sample_cache(cache, *scene, w, h, target);  // keeps the memory of the last image
}

// One unit of work, then a publication; false when cancelled by a newer scene. A cancelled
// stage leaves `dirty` at the class that redoes it, so the caches never mix two scenes.
bool ProgressiveRenderer::Impl::step() {
  const Clock::time_point start = Clock::now();
  std::atomic<long long> rays{0};
  ctx.rays = &rays;
  ChangeClass redo = ChangeClass::none;  // what a cancellation leaves to do
  bool ok = true;
  bool factors_done = false;  // the fused first pass builds the pixel factors too
  bool total_done = false;    // ... and, when only the total is shown, the frame's total image
  // The image size first (a restart or the next preview level), then the frame to fill.
  const bool restart = dirty == ChangeClass::full;
  const bool next_level = dirty == ChangeClass::none && level < options.preview_levels;
  SampleCache previous;  // next_level: the current resolution, kept until the next is complete
  const int previous_level = level;
  if (restart) {
    start_level(options.preview_levels > 0 ? 0 : options.preview_levels);
  } else if (next_level) {
    previous = std::move(cache);
    const bool skip = last_full_pass_ms >= 0 && last_full_pass_ms <= options.preview_budget_ms;
    // Its spare planes and refined buffers hold no data: the new image takes them now, its
    // planes in use once the new image is complete (reclaim_planes below).
    cache.spare = std::move(previous.spare);
    previous.spare.clear();
    cache.refined.plane = std::move(previous.refined.plane);
    start_level(skip ? options.preview_levels : level + 1);
  }
  const std::shared_ptr<RenderedFrame> frame =
      FramePool::make(frame_pool, cache.width, cache.height, worker_terms);
  // The first pass makes the total itself unless a term view wants the terms or the
  // environment is the background (its sky comes after the factors: combine_terms adds it).
  const bool sky_shown = ctx.plan.sky && scene->environment.as_background;
  Image* const total = worker_terms || sky_shown ? nullptr : &frame->images.total;
  // The environment's estimates belong to the cache's samples and slots as they are: an edit
  // that rewrites the slots (environment, light) or the samples (full) starts them again, from
  // the fast path. Edits below keep them (a material edit only recombines).
  if (dirty >= ChangeClass::environment) environment.reset();
  const int environment_steps =
      dirty == ChangeClass::none && samples_done() ? next_environment_steps(ctx, environment) : 0;
  if (restart) {
    redo = ChangeClass::full;
    ok = trace_single_sample(cache, ctx, factors, total);
    factors_done = total_done = true;
  } else if (dirty == ChangeClass::environment) {
    redo = ChangeClass::environment;  // its factors from the cached hits, no rays
    ok = recompute_environment_factors(cache, ctx);
  } else if (dirty == ChangeClass::texture) {
    redo = ChangeClass::texture;  // the maps at the cached hits, no rays
    ok = resample_textures(cache, ctx) &&
         (!ctx.plan.environment || recompute_environment_factors(cache, ctx));
  } else if (dirty == ChangeClass::light) {
    redo = ChangeClass::light;
    if (cache.samples() == 1 && cache.refined.spp == 0) {  // one pass: light and pixel factors
      ok = relight_single_sample(cache, ctx, factors, total);
      factors_done = total_done = true;
    } else {
      ok = recompute_light_factors(cache, ctx);
    }
  } else if (next_level) {
    // The next resolution is traced aside; the current one stays until it is complete.
    redo = ChangeClass::exponent;  // cancelled: the factors must be rebuilt from `previous`
    ok = trace_single_sample(cache, ctx, factors, total);
    factors_done = total_done = true;
    if (ok) {
      reclaim_planes(cache, std::move(previous));
    } else {
      SampleCache traced = std::move(cache);
      cache = std::move(previous);
      level = previous_level;
      reclaim_planes(cache, std::move(traced));
    }
  } else if (environment_steps > 0) {
    redo = ChangeClass::environment;  // cancelled: back to the fast path, estimates anew
    ok = add_environment_steps(cache, ctx, environment, environment_steps);
  } else if (dirty == ChangeClass::none && adaptive()) {
    redo = ChangeClass::exponent;  // cancelled: the factors are rebuilt from the centres
    ok = refine() && refine_pixel_factors(cache, ctx, factors);
    factors_done = true;
  } else if (dirty == ChangeClass::none) {
    // Double the samples each pass: 1, 2, 4, 8 ... up to the target.
    const int have = cache.samples();
    ok = add_samples(cache, ctx, std::min(have, scene->render.spp - have));
  }
  if (ok && dirty != ChangeClass::shade && !factors_done) {
    redo = std::max(redo, ChangeClass::exponent);
    ok = build_pixel_factors(cache, ctx, factors);
  }
  // The sky follows the camera, the samples and the environment's map and rotation.
  if (ok && ctx.plan.sky && dirty != ChangeClass::shade && dirty != ChangeClass::exponent) {
    ok = environment_sky(cache, ctx, factors);
  }
  ctx.rays = nullptr;
  if (!ok) {
    dirty = std::max(dirty, redo);
    if (cache.samples() == 0) dirty = ChangeClass::full;
    return false;
  }
  dirty = ChangeClass::none;
  if (!total_done || total == nullptr) combine_terms(factors, ctx, frame->images, worker_terms);
  const double pass_ms = ms_between(start, Clock::now());
  if ((restart || next_level) && level == options.preview_levels) last_full_pass_ms = pass_ms;
  publish(frame, pass_ms, rays.load(), converged_state());
  return true;
}

bool ProgressiveRenderer::Impl::refine() {
  // The total the centre samples make, what the rule looks at: the frame published last.
  std::shared_ptr<const RenderedFrame> centres;
  {
    std::lock_guard<std::mutex> lock(publish_mutex);
    centres = published;
  }
  std::vector<std::uint32_t> pixels = choose_refined_pixels(
      cache, centres->images.total, scene->render.aa_threshold, 0, cache.height);
  return trace_refined_samples(cache, ctx, std::move(pixels), scene->render.spp);
}

void ProgressiveRenderer::Impl::publish(std::shared_ptr<RenderedFrame> frame, double pass_ms,
                                        long long rays, bool converged) {
  FrameInfo& info = frame->info;
  info.generation = worker_generation;
  info.pass = pass++;
  info.width = cache.width;
  info.height = cache.height;
  info.spp = cached_spp();
  frame->refined = cache.refined.pixels;
  info.target_spp = scene->render.spp;
  info.pass_ms = pass_ms;
  info.since_change_ms = ms_between(worker_changed_at, Clock::now());
  info.rays = rays;
  info.converged = converged;
  info.cause = cause;
  std::function<void()> callback;
  {
    std::lock_guard<std::mutex> lock(publish_mutex);
    published = std::move(frame);
    callback = on_publish;
  }
  // The callback first: a caller woken by wait_converged then sees what the callback did.
  if (callback) callback();
  published_cv.notify_all();
}

ProgressiveRenderer::ProgressiveRenderer(ProgressiveOptions options)
    : m_impl(std::make_unique<Impl>(options)) {
  m_impl->worker_terms = options.terms;
  m_impl->worker = std::thread([impl = m_impl.get()] { impl->run(); });
}

ProgressiveRenderer::~ProgressiveRenderer() {
  {
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    m_impl->stop = true;
    m_impl->cancel.store(true);
  }
  m_impl->wake.notify_all();
  m_impl->worker.join();
}

std::uint64_t ProgressiveRenderer::set_scene(const Scene& scene) {
  auto copy = std::make_shared<const Scene>(scene);
  std::uint64_t generation;
  {
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    const bool was_paused = m_impl->paused;
    m_impl->paused = false;
    if (m_impl->last_set != nullptr && !diff_scenes(*m_impl->last_set, *copy).any) {
      generation = m_impl->generation;
      if (!was_paused) return generation;
      // pause()'s cancel: the worker goes on with the same scene (a pending one resets it when
      // taken in; resetting it now would let a pass for an older scene finish).
      if (m_impl->pending == nullptr) m_impl->cancel.store(false);
    } else {
      m_impl->last_set = copy;
      m_impl->pending = std::move(copy);
      generation = ++m_impl->generation;
      m_impl->changed_at = Clock::now();
      m_impl->cancel.store(true);  // work in flight is for an older scene
    }
  }
  m_impl->wake.notify_all();  // also resumes a paused worker on the same scene
  return generation;
}

void ProgressiveRenderer::pause() {
  {
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    m_impl->paused = true;
    m_impl->cancel.store(true);
  }
  m_impl->wake.notify_all();
}

void ProgressiveRenderer::set_terms(bool terms) {
  {
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    if (m_impl->terms == terms) return;
    m_impl->terms = terms;
  }
  m_impl->wake.notify_all();
}

std::shared_ptr<const RenderedFrame> ProgressiveRenderer::latest() const {
  std::lock_guard<std::mutex> lock(m_impl->publish_mutex);
  return m_impl->published;
}

bool ProgressiveRenderer::wait_converged(double timeout_ms) const {
  std::uint64_t generation;
  {
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    generation = m_impl->generation;
  }
  std::unique_lock<std::mutex> lock(m_impl->publish_mutex);
  return m_impl->published_cv.wait_for(
      lock, std::chrono::duration<double, std::milli>(timeout_ms), [&] {
        const auto& p = m_impl->published;
        return p != nullptr && p->info.generation == generation && p->info.converged;
      });
}

void ProgressiveRenderer::set_on_publish(std::function<void()> callback) {
  std::lock_guard<std::mutex> lock(m_impl->publish_mutex);
  m_impl->on_publish = std::move(callback);
}

}  // namespace gloss

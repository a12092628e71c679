#include "engine/progressive_renderer.h"

#include <pthread.h>

#include "engine/change_class.h"
#include "engine/progressive_state.h"
#include "engine/render_plan.h"
#include "scene/fields/scene_diff.h"

namespace gloss {

namespace {
using Clock = std::chrono::steady_clock;
}  // namespace

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
  if (scene == nullptr || changes_sky(*scene, *next, change)) sky_current = false;
  pass = 0;
  published_centres = false;  // the published frame shows an older scene
  adaptive_state.edit(change, cache);
  if (embree == nullptr || scene == nullptr || diff.geometry) {
    embree = std::make_unique<EmbreeScene>(*next);
  }
  scene = std::move(next);
  bind_scene(ctx, *scene, *embree);
  ctx.cancel = &cancel;
  dirty = std::max(dirty, change);
  return true;
}

void ProgressiveRenderer::Impl::publish(std::shared_ptr<RenderedFrame> frame, double pass_ms,
                                        long long rays, bool converged) {
  frame->refined = factors.refined_pixel;
  frame->info.refined_traced = refined_traced;
  published_centres = adaptive() && level == options.preview_levels && factors.samples == 1 &&
                      factors.refined_pixel.empty();
  publish_frame(std::move(frame), cache.width, cache.height, factors_spp(), pass_ms, rays,
                converged);
}

void ProgressiveRenderer::Impl::publish_frame(std::shared_ptr<RenderedFrame> frame, int width,
                                              int height, int spp, double pass_ms, long long rays,
                                              bool converged) {
  FrameInfo& info = frame->info;
  info.generation = worker_generation;
  info.pass = pass++;
  info.width = width;
  info.height = height;
  info.spp = spp;
  info.target_spp = scene->render.spp;
  info.pass_ms = pass_ms;
  info.since_change_ms = Impl::ms_between(worker_changed_at, Clock::now());
  info.rays = rays;
  info.converged = converged;
  info.cause = cause;
  const bool exact_path = ctx.plan.environment && ctx.environment.sampler != nullptr;
  info.env_target = exact_path ? scene->render.env_samples : 0;
  // The estimates belong to the full-size samples; a coarse preview shows the fast path.
  const bool full_size = width == scene->render.width && height == scene->render.height;
  info.env_steps = exact_path && full_size ? environment.steps : 0;
  {
    std::lock_guard<std::mutex> lock(mutex);
    first_in_flight = false;
    published_at = Clock::now();
  }
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
  // Named by the creating thread before the constructor returns, so a caller that sets thread
  // priorities by name (the editor's background_priority.h) sees the name from the start.
  pthread_setname_np(m_impl->worker.native_handle(), kEngineThreadName);
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
      // Work in flight is for an older scene and stops, unless it is a first image and nothing
      // was published for max_publish_gap_ms: then it completes and is shown before the newest
      // scene is taken, so edits faster than a pass (a drag, an animation) still move the image.
      const bool starved =
          m_impl->first_in_flight && Impl::ms_between(m_impl->published_at, m_impl->changed_at) >=
                                         m_impl->options.max_publish_gap_ms;
      if (!starved || was_paused) m_impl->cancel.store(true);
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

#include "editor/model/view/reference_preview.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "editor/model/document/document.h"
#include "reference/reference_renderer.h"

namespace gloss {

struct ReferencePreview::Impl {
  mutable std::mutex mutex;
  mutable std::condition_variable changed;  // a new scene, a publication, or quitting
  Scene scene;
  bool has_scene = false;
  std::uint64_t generation = 0;  // of `scene`
  std::uint64_t published = 0;   // generation of `frame`
  std::shared_ptr<const RenderedFrame> frame;
  std::function<void()> on_publish;
  std::atomic<bool> cancel{false};  // the pass in flight is for an older generation
  bool quit = false;
  std::thread worker;

  void run() {
    std::unique_lock<std::mutex> lock(mutex);
    while (true) {
      changed.wait(lock, [&] { return quit || (has_scene && published != generation); });
      if (quit) return;
      const Scene job = scene;
      const std::uint64_t job_generation = generation;
      cancel = false;
      lock.unlock();
      ReferenceOptions options;
      options.physical = true;
      options.spp = 1;
      options.cancel = &cancel;
      auto frame_out = std::make_shared<RenderedFrame>();
      const auto start = std::chrono::steady_clock::now();
      bool ok = true;
      try {
        frame_out->images = render_reference<double>(job, options);
      } catch (const std::exception&) {
        ok = false;  // an invalid document never reaches here (the command layer validates)
      }
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count();
      lock.lock();
      if (!ok || cancel || job_generation != generation) {
        if (!ok) published = job_generation;  // nothing to show for it; do not retry
        continue;
      }
      FrameInfo& info = frame_out->info;
      info.generation = job_generation;
      info.width = job.render.width;
      info.height = job.render.height;
      info.spp = info.target_spp = 1;
      info.pass_ms = info.since_change_ms = ms;
      info.converged = true;
      frame = std::move(frame_out);
      published = job_generation;
      std::function<void()> callback = on_publish;
      changed.notify_all();
      lock.unlock();
      if (callback) callback();
      lock.lock();
    }
  }
};

ReferencePreview::ReferencePreview() : m(std::make_unique<Impl>()) {
  m->worker = std::thread([this] { m->run(); });
}

ReferencePreview::~ReferencePreview() {
  {
    std::lock_guard<std::mutex> lock(m->mutex);
    m->quit = true;
    m->cancel = true;
  }
  m->changed.notify_all();
  m->worker.join();
}

std::uint64_t ReferencePreview::set_scene(const Scene& scene) {
  std::lock_guard<std::mutex> lock(m->mutex);
  if (m->has_scene && same_scene(m->scene, scene)) return m->generation;
  m->scene = scene;
  m->has_scene = true;
  ++m->generation;
  m->cancel = true;
  m->changed.notify_all();
  return m->generation;
}

std::shared_ptr<const RenderedFrame> ReferencePreview::latest() const {
  std::lock_guard<std::mutex> lock(m->mutex);
  return m->frame;
}

bool ReferencePreview::wait_converged(double timeout_ms) const {
  std::unique_lock<std::mutex> lock(m->mutex);
  return m->changed.wait_for(lock, std::chrono::duration<double, std::milli>(timeout_ms),
                             [&] { return m->has_scene && m->published == m->generation; });
}

void ReferencePreview::set_on_publish(std::function<void()> callback) {
  std::lock_guard<std::mutex> lock(m->mutex);
  m->on_publish = std::move(callback);
}

}  // namespace gloss

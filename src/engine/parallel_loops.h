#pragma once
// The renderer's parallel loops on oneTBB workers, over bands of whole image rows, with
// flush-to-zero and denormals-are-zero set in the worker for the duration of each chunk
// (denormal results at high shininess must not slow rendering down). They return false when
// cancelled.
#include <algorithm>
#include <atomic>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "engine/simd/denormals.h"

namespace gloss {

// Happens-before edges around a oneTBB parallel loop that ThreadSanitizer can see: Debian's
// libtbb is not built with TSan, so its own fork/join synchronisation is invisible to it and
// every cache written by one worker and read after the loop would be reported as a race.
// Costs two atomic operations per task, none per pixel.
class ForkJoinFence {
 public:
  ForkJoinFence() { m_count.store(0, std::memory_order_release); }  // fork: caller's writes
  void enter() const { (void)m_count.load(std::memory_order_acquire); }
  void leave() { m_count.fetch_add(1, std::memory_order_release); }
  void join() const { (void)m_count.load(std::memory_order_acquire); }  // after the loop

  // Marks one task body: enter on construction, leave on destruction (early returns included).
  class Task {
   public:
    explicit Task(ForkJoinFence& fence) : m_fence(fence) { m_fence.enter(); }
    ~Task() { m_fence.leave(); }
    Task(const Task&) = delete;
    Task& operator=(const Task&) = delete;

   private:
    ForkJoinFence& m_fence;
  };

 private:
  std::atomic<int> m_count{0};
};

// Runs f(i) for every chunk i in [0, count) on oneTBB workers, with FTZ/DAZ and the fences
// above; stops taking chunks once cancel turns true. Returns false when cancelled.
template <class F>
bool parallel_chunks(int count, const std::atomic<bool>* cancel, F&& f) {
  std::atomic<bool> stopped{false};
  ForkJoinFence fence;
  tbb::parallel_for(tbb::blocked_range<int>(0, count, 1),
                    [&](const tbb::blocked_range<int>& range) {
                      const ForkJoinFence::Task task(fence);
                      DenormalsOff denormals_off;
                      for (int i = range.begin(); i != range.end(); ++i) {
                        if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) {
                          stopped.store(true, std::memory_order_relaxed);
                          return;
                        }
                        f(i);
                      }
                    });
  fence.join();
  return !stopped.load();
}

// Rows of one band of parallel_rows: about 16 K pixels.
inline int band_rows(int width) {
  return width > 0 ? std::max(1, 16384 / width) : 1;
}

// Runs f(y0, y1) over bands of whole rows: the arrays a pass reads and writes stay a few long
// streams for the hardware prefetchers, where 32-pixel tiles hop 32 rows apart. Passes over the
// caches measured markedly faster that way, ray passes no slower (docs/engine.md, "Row bands").
// Band b covers rows [b * band_rows, (b + 1) * band_rows) clipped to the image.
template <class F>
bool parallel_rows(int width, int height, const std::atomic<bool>* cancel, F&& f) {
  const int rows = band_rows(width);
  return parallel_chunks((height + rows - 1) / rows, cancel,
                         [&](int band) { f(band * rows, std::min(height, (band + 1) * rows)); });
}

}  // namespace gloss

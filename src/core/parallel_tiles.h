#pragma once
// Runs f(x0, y0, x1, y1) over square tiles of a width x height image on oneTBB workers, with
// flush-to-zero and denormals-are-zero set in the worker for the duration of each tile (denormal
// results at high shininess must not slow rendering down). Returns false when cancelled.
#include <atomic>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <xmmintrin.h>

namespace gloss {

constexpr int kTileSize = 32;  // pixels; a multiple of the 4 x 4 ray packets

// Sets FTZ and DAZ in MXCSR for its lifetime, then restores the caller's mode.
class DenormalsOff {
 public:
  DenormalsOff() : m_saved(_mm_getcsr()) { _mm_setcsr(m_saved | 0x8040u); }
  ~DenormalsOff() { _mm_setcsr(m_saved); }
  DenormalsOff(const DenormalsOff&) = delete;
  DenormalsOff& operator=(const DenormalsOff&) = delete;

 private:
  unsigned m_saved;
};

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

template <class F>
bool parallel_tiles(int width, int height, const std::atomic<bool>* cancel, F&& f) {
  const int tiles_x = (width + kTileSize - 1) / kTileSize;
  const int tiles_y = (height + kTileSize - 1) / kTileSize;
  std::atomic<bool> stopped{false};
  ForkJoinFence fence;
  tbb::parallel_for(tbb::blocked_range<int>(0, tiles_x * tiles_y, 1),
                    [&](const tbb::blocked_range<int>& range) {
                      const ForkJoinFence::Task task(fence);
                      DenormalsOff denormals_off;
                      for (int tile = range.begin(); tile != range.end(); ++tile) {
                        if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) {
                          stopped.store(true, std::memory_order_relaxed);
                          return;
                        }
                        const int x0 = (tile % tiles_x) * kTileSize;
                        const int y0 = (tile / tiles_x) * kTileSize;
                        f(x0, y0, x0 + kTileSize < width ? x0 + kTileSize : width,
                          y0 + kTileSize < height ? y0 + kTileSize : height);
                      }
                    });
  fence.join();
  return !stopped.load();
}

}  // namespace gloss

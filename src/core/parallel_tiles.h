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

template <class F>
bool parallel_tiles(int width, int height, const std::atomic<bool>* cancel, F&& f) {
  const int tiles_x = (width + kTileSize - 1) / kTileSize;
  const int tiles_y = (height + kTileSize - 1) / kTileSize;
  std::atomic<bool> stopped{false};
  tbb::parallel_for(tbb::blocked_range<int>(0, tiles_x * tiles_y, 1),
                    [&](const tbb::blocked_range<int>& range) {
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
  return !stopped.load();
}

}  // namespace gloss

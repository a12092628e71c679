#pragma once
// Stores of whole lane arrays past the CPU caches (non-temporal), for arrays written once and
// read much later (the per-sample cache, the total image of the first pass): a full, aligned
// line is written without first reading it. Callers fall back to plain copies for partial or
// unaligned lines, and end each task with finish_streaming_stores.
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "engine/simd/lanes.h"

namespace gloss {

// Streams kLanes 32-bit lanes to dst when dst is 64-byte aligned (one cache line) and the build
// has AVX-512; returns false (nothing written) otherwise.
template <class T>
inline bool stream_lane_line(const T* lanes, T* dst) {
  static_assert(sizeof(T) == 4 && kLanes == 16, "one 64-byte line of 32-bit lanes");
#if defined(__AVX512F__)
  if (reinterpret_cast<std::uintptr_t>(dst) % 64 == 0) {
    _mm512_stream_si512(reinterpret_cast<__m512i*>(dst), _mm512_loadu_si512(lanes));
    return true;
  }
#else
  (void)lanes;
  (void)dst;
#endif
  return false;
}

// Streams the kLanes pixels (r, g, b) of rgb to dst when dst is 16-byte aligned (192 bytes in
// 16-byte pieces: glm::vec3 images are only 4-byte aligned in general); returns false
// (nothing written) otherwise.
inline bool stream_rgb_lanes(const float* rgb, float* dst) {
#if defined(__SSE2__)
  if (reinterpret_cast<std::uintptr_t>(dst) % 16 == 0) {
    for (int k = 0; k < 3 * kLanes; k += 4) _mm_stream_ps(dst + k, _mm_loadu_ps(rgb + k));
    return true;
  }
#else
  (void)rgb;
  (void)dst;
#endif
  return false;
}

// Orders this thread's streaming stores before whatever it does next (the end of a task).
inline void finish_streaming_stores() {
#if defined(__SSE2__)
  _mm_sfence();
#endif
}

}  // namespace gloss

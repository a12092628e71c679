#pragma once
// Whole-packet tests over 16 lanes. GCC compiles the plain loops (a count or an OR over the
// lanes) to a horizontal chain of extracts and adds or ors, some ten dependent steps per
// packet; an AVX-512 compare to a mask and a popcount are two.
#include <cstdint>

#if defined(__AVX512F__)
#include <immintrin.h>
#endif

#include "engine/simd/lanes.h"

namespace gloss {

static_assert(kLanes == 16, "the AVX-512 forms below test one 512-bit register of 32-bit lanes");

// Lanes that are not zero (Embree's valid masks: -1 or 0).
inline int count_set_lanes(const std::int32_t* lanes) {
#if defined(__AVX512F__)
  const __m512i v = _mm512_loadu_si512(lanes);
  return __builtin_popcount(_mm512_test_epi32_mask(v, v));
#else
  int n = 0;
  for (int i = 0; i < kLanes; ++i) n += lanes[i] != 0 ? 1 : 0;
  return n;
#endif
}

// Whether some lane differs from value (a NaN lane does).
inline bool any_lane_differs(const float* lanes, float value) {
#if defined(__AVX512F__)
  return _mm512_cmp_ps_mask(_mm512_loadu_ps(lanes), _mm512_set1_ps(value), _CMP_NEQ_UQ) != 0;
#else
  bool any = false;
  for (int i = 0; i < kLanes; ++i) any |= lanes[i] != value;
  return any;
#endif
}

// Whether every lane is negative (every sample of a packet missed: material or object -1).
inline bool all_lanes_negative(const std::int32_t* lanes) {
#if defined(__AVX512F__)
  return _mm512_cmpge_epi32_mask(_mm512_loadu_si512(lanes), _mm512_setzero_si512()) == 0;
#else
  bool all = true;
  for (int i = 0; i < kLanes; ++i) all &= lanes[i] < 0;
  return all;
#endif
}

// lanes[0] when all 16 lanes hold that value and it is not negative, else -1 (one material or
// object for a whole packet, the common case, which callers then treat as a scalar).
inline std::int32_t common_lane_value(const std::int32_t* lanes) {
  const std::int32_t first = lanes[0];
#if defined(__AVX512F__)
  const bool all =
      _mm512_cmpeq_epi32_mask(_mm512_loadu_si512(lanes), _mm512_set1_epi32(first)) == 0xffff;
#else
  bool all = true;
  for (int i = 1; i < kLanes; ++i) all &= lanes[i] == first;
#endif
  return all && first >= 0 ? first : -1;
}

}  // namespace gloss

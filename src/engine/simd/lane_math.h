#pragma once
// Vector maths over kLanes doubles that GCC does not find by itself.
#include <cmath>

#if defined(__AVX512F__)
#include <immintrin.h>
#endif

#include "engine/simd/lanes.h"

namespace gloss {

// Scales the kLanes vectors (x[i], y[i], z[i]) to unit length; the arrays are 64-byte aligned.
// With AVX-512: the 14-bit reciprocal square root estimate and two Newton steps (14 -> 28 -> 56
// bits; lengths within a few double ulp of 1), cheaper per lane than a double square root and
// division (docs/engine.md, "Normalising directions"). Results then differ from the scalar
// fallback (1 / sqrt) by a few double ulp: far inside the accuracy contract.
inline void normalize_lanes(double* x, double* y, double* z) {
#if defined(__AVX512F__)
  static_assert(kLanes % 8 == 0, "whole 8-double registers");
  const __m512d three_halves = _mm512_set1_pd(1.5), half = _mm512_set1_pd(0.5);
  for (int k = 0; k < kLanes; k += 8) {
    const __m512d vx = _mm512_load_pd(x + k), vy = _mm512_load_pd(y + k),
                  vz = _mm512_load_pd(z + k);
    const __m512d n2 = _mm512_fmadd_pd(vx, vx, _mm512_fmadd_pd(vy, vy, _mm512_mul_pd(vz, vz)));
    const __m512d half_n2 = _mm512_mul_pd(half, n2);
    __m512d r = _mm512_maskz_rsqrt14_pd(0xff, n2);  // masked: see lane_gather.h
    for (int step = 0; step < 2; ++step) {          // r (3/2 - n2 r^2 / 2)
      r = _mm512_mul_pd(r, _mm512_fnmadd_pd(half_n2, _mm512_mul_pd(r, r), three_halves));
    }
    _mm512_store_pd(x + k, _mm512_mul_pd(vx, r));
    _mm512_store_pd(y + k, _mm512_mul_pd(vy, r));
    _mm512_store_pd(z + k, _mm512_mul_pd(vz, r));
  }
#else
  for (int i = 0; i < kLanes; ++i) {
    const double r = 1.0 / std::sqrt(x[i] * x[i] + y[i] * y[i] + z[i] * z[i]);
    x[i] *= r;
    y[i] *= r;
    z[i] *= r;
  }
#endif
}

}  // namespace gloss

#pragma once
// The map coordinates (u, t) of kLanes map-frame unit directions at once (the contract's mapping,
// shading/environment.h map_uv: u = 0.5 + atan2(x, -z) / (2 pi), t = acos(y) / pi, u = 0.5 at
// the poles). The C library's atan2f and acosf are scalar calls (libmvec has no vector atan2f
// or acosf), and for the fast path they cost about as much per lane as the rest of the pixel;
// here they are one polynomial the compiler vectorises: Cephes' atanf, the same formula and
// constants as shaders/environment.glsl's gloss_env_atan2, so the CPU fast path and the GLSL
// path compute the same coordinates (both within about 1e-7 of the exact ones: far below a
// texel of the finest map, 1 / 8192).
#include <cmath>

#include "engine/simd/lanes.h"

namespace gloss {

// atan2(y, x) in [-pi, pi] to about 1e-7 relative: reduced to t = min / max in [0, 1], then to
// |t| <= tan(pi / 8) by atan t = pi / 4 + atan((t - 1) / (t + 1)), where the odd polynomial
// holds. Every branch is a select, so a loop over lanes vectorises. x = y = 0 gives NaN (0 / 0):
// the caller chooses the pole's value itself.
inline float polynomial_atan2(float y, float x) {
  const float ay = std::fabs(y), ax = std::fabs(x);
  const bool swap = ay > ax;
  const float t = (swap ? ax : ay) / (swap ? ay : ax);
  const bool reduce = t > 0.41421356f;
  const float s = reduce ? (t - 1.0f) / (t + 1.0f) : t;
  const float z = s * s;
  float a = (reduce ? 0.78539816f : 0.0f) +
            ((((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z -
              3.33329491539e-1f) *
                 z * s +
             s);
  a = swap ? 1.57079633f - a : a;
  a = x < 0.0f ? 3.14159265f - a : a;
  return y < 0.0f ? -a : a;
}

// (u[i], t[i]) of the unit map-frame directions (x[i], y[i], z[i]); the arrays are 64-byte
// aligned. acos(y) is atan2(sqrt(1 - y^2), y) with 1 - y^2 as (1 - y)(1 + y), exact near the
// poles (as the GLSL path).
inline void map_uv_lanes(const float* x, const float* y, const float* z, float* u, float* t) {
  constexpr float kInvTwoPi = 0.159154943091895335769f, kInvPi = 0.318309886183790671538f;
#pragma omp simd aligned(x, y, z, u, t : 64)
  for (int i = 0; i < kLanes; ++i) {
    const bool pole = x[i] == 0.0f && z[i] == 0.0f;
    const float phi = pole ? 0.0f : polynomial_atan2(x[i], -z[i]);
    // Clamped with selects: GCC 12 vectorises neither fmaxf / fminf (their NaN rules) nor
    // std::min / std::max here (they return references to temporaries).
    const float yc = y[i] < -1.0f ? -1.0f : y[i], c = yc > 1.0f ? 1.0f : yc;
    u[i] = 0.5f + phi * kInvTwoPi;
    t[i] = polynomial_atan2(std::sqrt((1.0f - c) * (1.0f + c)), c) * kInvPi;
  }
}

}  // namespace gloss

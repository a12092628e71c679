#include "power_lanes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fast_power.h"
#include "lane_gather.h"

// glibc's libmvec has vector variants of powf (_ZGV{b,c,d,e}N*vv_powf, glibc >= 2.22), but
// <math.h> declares them only under -ffast-math, which the renderer must not use (its NaN and
// infinity guards must keep their meaning). Declaring the SIMD variant here lets the loop below
// call them under -fopenmp-simd; the library is linked as mvec (src/core/CMakeLists.txt).
extern "C" __attribute__((__simd__("notinbranch"))) float powf(float, float) noexcept;

namespace gloss {

MaterialExponents material_exponents(const Scene& scene) {
  MaterialExponents e;
  for (const Material& m : scene.materials) {
    e.alpha.push_back(m.shininess);
    // c^alpha >= 2^-120  <=>  c >= 2^(-120 / alpha); alpha = 0 keeps every c > 0.
    e.floor.push_back(m.shininess > 0.0f
                          ? static_cast<float>(std::exp2(-120.0 / static_cast<double>(m.shininess)))
                          : 0.0f);
  }
  if (e.alpha.empty()) {  // lanes without a material gather entry 0
    e.alpha.push_back(0.0f);
    e.floor.push_back(0.0f);
  }
  return e;
}

void specular_power_lanes(const MaterialExponents& exponents, const std::int32_t* material,
                          const float* c, float* out, int n, PowMode mode) {
  alignas(64) float base[kMaxPowerLanes], alpha[kMaxPowerLanes], floor[kMaxPowerLanes];
  alignas(64) std::int32_t index[kMaxPowerLanes];
  for (int i = 0; i < n; ++i) index[i] = std::max(material[i], 0);
  if (n == kMaxPowerLanes) {  // a handful of materials, in L1
    gather16(exponents.alpha.data(), index, alpha);
    gather16(exponents.floor.data(), index, floor);
  } else {
    for (int i = 0; i < n; ++i) {
      alpha[i] = exponents.alpha[static_cast<std::size_t>(index[i])];
      floor[i] = exponents.floor[static_cast<std::size_t>(index[i])];
    }
  }
  for (int i = 0; i < n; ++i) {
    floor[i] = material[i] < 0 ? std::numeric_limits<float>::infinity() : floor[i];
  }
  if (mode == PowMode::fast) {
    for (int i = 0; i < n; ++i)
      out[i] = c[i] >= floor[i] ? fast_specular_power(c[i], alpha[i]) : 0.0f;
    return;
  }
  // Lanes whose result is fixed (0 or 1) call powf(1, 1): the vector powf then stays on its fast
  // path. The arguments go through memory so GCC cannot fold the selects into the call (it
  // otherwise passes the raw lanes, result selects being enough for correctness but not speed).
  int needed = 0;  // lanes that need powf at all: c^1 = c exactly (matte walls have alpha 1)
  for (int i = 0; i < n; ++i) {
    const bool fixed = !(c[i] >= floor[i]) || c[i] >= 1.0f || alpha[i] == 0.0f;
    base[i] = fixed ? 1.0f : c[i];
    alpha[i] = fixed ? 1.0f : alpha[i];
    needed += alpha[i] != 1.0f ? 1 : 0;
  }
  if (needed > 0) {
#pragma omp simd
    for (int i = 0; i < n; ++i) base[i] = powf(base[i], alpha[i]);
  }
  for (int i = 0; i < n; ++i) out[i] = c[i] >= floor[i] && c[i] > 0.0f ? base[i] : 0.0f;
}

}  // namespace gloss

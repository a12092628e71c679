#include "engine/shade/power_lanes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/simd/lane_gather.h"
#include "engine/simd/lane_mask.h"
#include "shading/fast_power.h"
#include "shading/shading.h"

// glibc's libmvec has vector variants of powf (_ZGV{b,c,d,e}N*vv_powf, glibc >= 2.22), but
// <math.h> declares them only under -ffast-math, which the renderer must not use (its NaN and
// infinity guards must keep their meaning). Declaring the SIMD variant here lets the loop below
// call them under -fopenmp-simd; the library is linked as mvec (gloss_libmvec,
// third_party/dependencies.cmake).
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

void scale_exponents(const MaterialExponents& exponents, const std::int32_t* material,
                     const float* scale, int n, bool energy, ShadingModel model,
                     ScaledExponent& out) {
  alignas(64) float material_alpha[kLanes], lane_scale[kLanes];
  alignas(64) std::int32_t index[kLanes];
  for (int i = 0; i < kLanes; ++i) {
    index[i] = i < n ? std::max(material[i], 0) : 0;
    lane_scale[i] = i < n ? scale[i] : 1.0f;
  }
  const LaneGather by_material(index);  // a handful of materials: a permute, no gather
  by_material(exponents.alpha.data(), exponents.alpha.size(), material_alpha);
  for (int i = 0; i < kLanes; ++i) {
    out.alpha[i] = material_alpha[i] * lane_scale[i];
    out.floor[i] = out.alpha[i] > 0.0f ? std::exp2(-120.0f / out.alpha[i]) : 0.0f;
  }
  out.energy_normalized = energy;
  if (!energy) return;
  for (int i = 0; i < kLanes; ++i) {
    out.energy[i] =
        energy_normalization(model, out.alpha[i]) / energy_normalization(model, material_alpha[i]);
  }
}

namespace {

// specular_power_lanes on exactly 16 lanes: loops of a fixed count, which GCC turns into
// straight vector code (with a run-time count it adds copies, checks and remainder loops).
// With weight, out = weight * c^alpha (0 on missed lanes) in the same loop: the powers then
// need no trip through memory before their only use. scaled: a shininess map's exponents,
// floors and normalisations (scale_exponents), in place of the materials'.
void power16(const MaterialExponents& exponents, const std::int32_t* mat, const float* cos,
             const float* weight, float* out, PowMode mode, const ScaledExponent* scaled) {
  alignas(64) float base[kLanes], alpha[kLanes], floor[kLanes];
  if (scaled != nullptr) {
    for (int i = 0; i < kLanes; ++i) {
      alpha[i] = scaled->alpha[i];
      floor[i] = scaled->floor[i];
    }
  } else {
    alignas(64) std::int32_t index[kLanes];
    for (int i = 0; i < kLanes; ++i) index[i] = std::max(mat[i], 0);
    const LaneGather by_material(index);  // a handful of materials: a permute, no gather
    by_material(exponents.alpha.data(), exponents.alpha.size(), alpha);
    by_material(exponents.floor.data(), exponents.floor.size(), floor);
  }
  for (int i = 0; i < kLanes; ++i) {
    floor[i] = mat[i] < 0 ? std::numeric_limits<float>::infinity() : floor[i];
  }
  if (mode == PowMode::fast) {
    for (int i = 0; i < kLanes; ++i) {
      base[i] = cos[i] >= floor[i] ? fast_specular_power(cos[i], alpha[i]) : 0.0f;
    }
  } else {
    // Lanes whose result is fixed (0 or 1) call powf(1, 1): the vector powf then stays on its
    // fast path. The arguments go through memory so GCC cannot fold the selects into the call
    // (it otherwise passes the raw lanes, result selects being enough for correctness but not
    // speed).
    for (int i = 0; i < kLanes; ++i) {
      const bool fixed = !(cos[i] >= floor[i]) || cos[i] >= 1.0f || alpha[i] == 0.0f;
      base[i] = fixed ? 1.0f : cos[i];
      alpha[i] = fixed ? 1.0f : alpha[i];
    }
    if (any_lane_differs(alpha, 1.0f)) {  // else c^1 = c exactly (matte walls have alpha 1)
#pragma omp simd
      for (int i = 0; i < kLanes; ++i) base[i] = powf(base[i], alpha[i]);
    }
    for (int i = 0; i < kLanes; ++i) {
      base[i] = cos[i] >= floor[i] && cos[i] > 0.0f ? base[i] : 0.0f;
    }
  }
  if (scaled != nullptr && scaled->energy_normalized) {  // recombination applies the material's
    for (int i = 0; i < kLanes; ++i) base[i] *= scaled->energy[i];
  }
  if (weight == nullptr) {
    for (int i = 0; i < kLanes; ++i) out[i] = base[i];
  } else {
    for (int i = 0; i < kLanes; ++i) out[i] = mat[i] < 0 ? 0.0f : weight[i] * base[i];
  }
}

// power16 on n <= 16 lanes. Always 16 lanes (fewer are padded as missed): every call runs the
// same code, so a run clipped at the image's edge gets the same bits as a full one (the vector
// and scalar powf of a loop's remainder may differ by an ulp).
void power_lanes(const MaterialExponents& exponents, const std::int32_t* material, const float* c,
                 const float* weight, float* out, int n, PowMode mode,
                 const ScaledExponent* scaled = nullptr) {
  if (n == kLanes) {
    power16(exponents, material, c, weight, out, mode, scaled);
    return;
  }
  alignas(64) float cos[kLanes], w[kLanes], result[kLanes];
  alignas(64) std::int32_t mat[kLanes];
  for (int i = 0; i < kLanes; ++i) {
    cos[i] = i < n ? c[i] : 0.0f;
    mat[i] = i < n ? material[i] : -1;
    w[i] = i < n && weight != nullptr ? weight[i] : 0.0f;
  }
  // scaled's lanes past n are already those of no material at scale 1 (scale_exponents).
  power16(exponents, mat, cos, weight != nullptr ? w : nullptr, result, mode, scaled);
  for (int i = 0; i < n; ++i) out[i] = result[i];
}
}  // namespace

void specular_power_lanes(const MaterialExponents& exponents, const std::int32_t* material,
                          const float* c, float* out, int n, PowMode mode) {
  power_lanes(exponents, material, c, nullptr, out, n, mode);
}

void specular_lanes(const MaterialExponents& exponents, const std::int32_t* material,
                    const float* c, const float* weight, float* out, int n, PowMode mode,
                    const ScaledExponent* scaled) {
  power_lanes(exponents, material, c, weight, out, n, mode, scaled);
}

void scaled_power_lanes(const MaterialExponents& exponents, const std::int32_t* material,
                        const float* c, float* out, int n, PowMode mode,
                        const ScaledExponent& scaled) {
  power_lanes(exponents, material, c, nullptr, out, n, mode, &scaled);
}

}  // namespace gloss

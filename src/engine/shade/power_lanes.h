#pragma once
// c^alpha over short arrays of lanes (the 16 samples of a packet, or a run of pixels): the
// contract of shading.h's specular_power, vectorized. Exact mode calls glibc's libmvec powf
// (its vector variants, measured cheaper per lane than scalar powf:
// docs/engine.md, "Vector powf"); fast mode is fast_specular_power's polynomial, inlined so it
// vectorizes too.
#include <cstdint>
#include <vector>

#include "engine/simd/lanes.h"
#include "scene/render_settings.h"
#include "scene/scene.h"

namespace gloss {

// Per material: the exponent, and the cosine below which c^alpha < 2^-120. Such results count
// as zero: they are invisible (far below the contract's 1e-4) and would send libmvec's powf to
// its slow per-lane path for underflow, several times the cost of a normal lane
// (docs/engine.md, "Vector powf").
struct MaterialExponents {
  std::vector<float> alpha;
  std::vector<float> floor;
};

MaterialExponents material_exponents(const Scene& scene);

// out[i] = c[i]^alpha(material[i]) per specular_power, for i < n <= kLanes; lanes with
// material < 0 get 0. c, material and out must not overlap.
void specular_power_lanes(const MaterialExponents& exponents, const std::int32_t* material,
                          const float* c, float* out, int n, PowMode mode);

// A shininess map's part in c^alpha (docs/engine.md, "Maps"): each lane's exponent is its
// material's times scale[i], and with energy normalisation on the power is also multiplied by
// the lane's normalisation over its material's (recombination applies the material's).
struct ScaledExponent {
  alignas(64) float scale[kLanes];
  bool energy = false;
  ShadingModel model = ShadingModel::phong;
};

// out[i] = weight[i] * c[i]^alpha(material[i]), 0 where material < 0: the same powers, in
// the loop that makes them; scaled: a shininess map's exponents.
void specular_lanes(const MaterialExponents& exponents, const std::int32_t* material,
                    const float* c, const float* weight, float* out, int n, PowMode mode,
                    const ScaledExponent* scaled = nullptr);

// specular_power_lanes with a shininess map's exponents.
void scaled_power_lanes(const MaterialExponents& exponents, const std::int32_t* material,
                        const float* c, float* out, int n, PowMode mode,
                        const ScaledExponent& scaled);

}  // namespace gloss

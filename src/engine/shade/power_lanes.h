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
// material's times the map's scale, and with energy normalisation on the power is also
// multiplied by the lane's normalisation over its material's (recombination applies the
// material's). None of it depends on the light: scale_exponents makes it once per packet (or run
// of lanes), and every light's powers read it.
struct ScaledExponent {
  alignas(64) float alpha[kLanes];   // the lane's exponent
  alignas(64) float floor[kLanes];   // c below which c^alpha counts as 0 (MaterialExponents)
  alignas(64) float energy[kLanes];  // normalisation of alpha over the material's exponent's
  bool energy_normalized = false;    // energy[] is set and multiplies the powers
};

// The ScaledExponent of n <= kLanes lanes of materials `material` (< 0: none; its lanes read
// material 0's, as the powers gather them) whose shininess multipliers are `scale`; the lanes
// past n have no material and scale 1. With `energy`, the normalisations of `model`.
void scale_exponents(const MaterialExponents& exponents, const std::int32_t* material,
                     const float* scale, int n, bool energy, ShadingModel model,
                     ScaledExponent& out);

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

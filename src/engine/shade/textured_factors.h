#pragma once
// Per-pixel factors of a plan with maps (docs/engine.md, "Maps"). With one sample per pixel the
// sample's texel channels multiply the recombined terms (borrow_texels). With more samples, and
// for refined pixels and further materials, each material group of a pixel keeps a textured
// record: the means over its samples of
//   [0, 3)             the ambient multiplier T_a (rgb)
//   [3, 6)             the emission multiplier T_e
//   [6 + 6 k, 9 + 6 k) T_d times slot k's diffuse factor
//   [9 + 6 k, 12 + 6 k) T_s times slot k's specular factor (c^alpha included)
// so that every constant edit stays a recombination, exactly (the contract is linear in ka, kd,
// ks, ke and the light colours per channel; the means of products are not products of means).
#include <cstddef>

#include "engine/render_context.h"
#include "engine/shade/pixel_factors.h"
#include "engine/shade/power_lanes.h"
#include "engine/trace/sample_cache.h"

namespace gloss {

inline std::size_t textured_stride(std::size_t slots) {
  return 6 + 6 * slots;
}

// Whether the plan's per-pixel factors need textured records (some colour map varies).
inline bool has_colour_texels(const TexturePlan& plan) {
  return plan.kd || plan.ka || plan.ks || plan.ke;
}

// Points out's texel channels at plane's (one sample per pixel), or clears them.
void borrow_texels(const SamplePlane& plane, const RenderPlan& plan, PixelFactors& out);

// Adds one sample to a record: texel (the sample's channels in the plan's order), its slots'
// diffuse and specular factors (one per slot).
void add_textured_sample(const TexturePlan& plan, const float* texel, std::size_t slots,
                         const float* diffuse, const float* specular, float* record);

// Sample `index` of a plane as add_textured_sample reads it: its texel channels into texel, its
// slots' diffuse factors into diffuse (specular factors, c^alpha included, are the caller's).
void sample_texels(const SamplePlane& plane, std::size_t index, float* texel, float* diffuse);

// The scaled exponents (scale_exponents) of n lanes of materials `material` whose shininess
// multipliers are alpha_scale, made in storage, with the scene's energy normalisation and model
// (alpha_scale null: the plan has no shininess map, or kLanes lanes that all missed: returns
// null). Once per packet or run: every light's powers read them.
const ScaledExponent* scaled_exponents(const RenderContext& ctx, const MaterialExponents& exponents,
                                       const std::int32_t* material, const float* alpha_scale,
                                       int n, ScaledExponent& storage);

}  // namespace gloss

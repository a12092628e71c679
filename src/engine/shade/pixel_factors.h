#pragma once
// Per-pixel factors: the shading contract is linear in ka, kd, ks, ke and the light colours, so
// the samples of a pixel are summed once per material they hit into
//   weight     = share of samples on that material
//   diffuse_i  = mean over those samples of ndl * att * vis       (per planned light i)
//   specular_i = mean over those samples of att * vis * c^alpha    (per planned light i)
// and any edit of constants or colours is a cheap recombination (combine_terms) with no rays.
// A pixel keeps its first material in the dense arrays; further materials (silhouettes) go to
// a short list of extras. With one sample per pixel the weight is 1 on a hit and the background
// share 1 on a miss, so those two arrays stay empty. Bytes per pixel: 4 + 8 per planned light,
// plus 8 with more than one sample, plus the extras.
#include <array>
#include <cstdint>
#include <vector>

#include "base/image.h"
#include "base/uninitialized_buffer.h"
#include "engine/render_context.h"
#include "engine/shade/power_lanes.h"
#include "engine/trace/sample_cache.h"
#include "engine/trace/texture_lanes.h"

namespace gloss {

struct PixelFactors {
  int width = 0, height = 0;
  int samples = 0;         // samples per pixel summed in
  std::size_t lights = 0;  // planned lights
  // Dense arrays, fully written by each build (so left uninitialised on resize).
  UninitializedBuffer<std::int32_t> material;  // first material hit, -1 when none
  UninitializedBuffer<float> weight;           // share of samples on it (empty: samples == 1)
  UninitializedBuffer<float> background;       // share of samples that missed (empty: samples == 1)
  UninitializedBuffer<float> diffuse, specular;  // [light * pixels + pixel]
  // Further materials of mixed pixels, in pixel order.
  std::vector<std::uint32_t> extra_pixel;
  std::vector<std::int32_t> extra_material;
  std::vector<float> extra_weight;
  std::vector<float> extra_diffuse, extra_specular;  // [extra * lights + light]
  // Adaptive sampling (samples == 1 for the centres): the refined pixels, ascending, with their
  // first material's weight and their background share; their factor means are in the dense
  // arrays like any pixel's.
  std::vector<std::uint32_t> refined_pixel;
  std::vector<float> refined_weight, refined_background;
  // With an environment (RenderPlan::sky): per pixel the mean over its samples of the map's
  // radiance at intensity 1 where they missed (environment/environment_stage.h); empty
  // otherwise.
  std::vector<glm::vec3> sky;
  // Maps (docs/engine.md, "Maps"; render_plan.h TexturePlan). With one sample per pixel the
  // multipliers are the sample's texel channels, borrowed from the cache's plane 0 (the factors
  // are used with the cache they were built from: its plane outlives them). With more samples a
  // pixel's factors per material group are textured records (textured_factors.h): the means of
  // the multipliers times the factors, per channel, in `textured` (uniform sampling's pixels),
  // `refined_textured` (refined pixels) and `extra_textured` (further materials).
  std::size_t texel_channels = 0;
  std::array<const float*, kMaxTexelChannels> texel{};
  std::size_t textured_stride = 0;  // floats per record; 0 without colour maps
  std::vector<float> textured, refined_textured, extra_textured;

  std::size_t bytes() const;
};

// Sums the cache's planes into per-pixel factors with the scene's exponents, model and pow mode.
// false when cancelled (the factors are then incomplete).
bool build_pixel_factors(const SampleCache& cache, const RenderContext& ctx, PixelFactors& out);

// Adaptive sampling's centre image alone: the factors of plane 0 as one sample per pixel, with
// no refined pixels (what build_pixel_factors makes of a cache without refined samples).
// false when cancelled (the factors are then incomplete).
bool build_centre_factors(const SampleCache& cache, const RenderContext& ctx, PixelFactors& out);

// Adaptive sampling: turns out, the factors of the cache's centre samples (one sample per
// pixel), into those of centres plus refined samples, summing only the refined pixels (none
// when the cache has no refined samples). false when cancelled (out is then incomplete).
bool refine_pixel_factors(const SampleCache& cache, const RenderContext& ctx, PixelFactors& out);

// Sizes out for a width x height region summed from `samples` samples, with no extras yet.
void size_pixel_factors(PixelFactors& out, int width, int height, int samples, std::size_t lights);

// Each object's material index (object_material of single_sample_coverage).
std::vector<std::int32_t> object_materials(const Scene& scene);

// The factors of n <= kLanes pixels covered by one sample each, from that sample's
// object index and one light's factors (cosine: the model's). Shared by build_pixel_factors at
// 1 spp and the fused first pass (single_sample_pass.h), so both give the same bits.
void single_sample_coverage(const std::vector<std::int32_t>& object_material,
                            const std::int32_t* object, int n, std::int32_t* material);
void single_sample_light(const MaterialExponents& exponents, PowMode mode,
                         const std::int32_t* material, const float* diffuse_weight,
                         const float* spec_weight, const float* cosine, int n, float* diffuse,
                         float* specular, const ScaledExponent* scaled = nullptr);

// Recombines factors with the scene's material constants, light colours, ambient and background
// into out.total (and the four term images when terms is set). out is resized as needed.
void combine_terms(const PixelFactors& factors, const RenderContext& ctx, TermImages& out,
                   bool terms);

}  // namespace gloss

#include "engine/shade/textured_factors.h"

#include "engine/simd/lane_mask.h"

namespace gloss {

void borrow_texels(const SamplePlane& plane, const RenderPlan& plan, PixelFactors& out) {
  out.texel_channels = has_colour_texels(plan.textures) ? plane.texels.size() : 0;
  out.texel.fill(nullptr);
  for (std::size_t c = 0; c < out.texel_channels; ++c) out.texel[c] = plane.texels[c].data();
}

void sample_texels(const SamplePlane& plane, std::size_t index, float* texel, float* diffuse) {
  for (std::size_t c = 0; c < plane.texels.size(); ++c) texel[c] = plane.texels[c][index];
  for (std::size_t k = 0; k < plane.lights.size(); ++k) {
    diffuse[k] = plane.lights[k].diffuse_weight[index];
  }
}

void add_textured_sample(const TexturePlan& plan, const float* texel, std::size_t slots,
                         const float* diffuse, const float* specular, float* record) {
  auto multiplier = [&](int channel, int c) { return channel >= 0 ? texel[channel + c] : 1.0f; };
  const int kd = plan.kd_channel(), ka = plan.ka_channel(), ks = plan.ks_channel(),
            ke = plan.ke_channel();
  for (int c = 0; c < 3; ++c) {
    record[c] += multiplier(ka, c);
    record[3 + c] += multiplier(ke, c);
  }
  for (std::size_t k = 0; k < slots; ++k) {
    const float d = diffuse[k], s = specular[k];
    float* slot = record + 6 + 6 * k;
    for (int c = 0; c < 3; ++c) {
      slot[c] += multiplier(kd, c) * d;
      slot[3 + c] += multiplier(ks, c) * s;
    }
  }
}

const ScaledExponent* scaled_exponents(const RenderContext& ctx, const MaterialExponents& exponents,
                                       const std::int32_t* material, const float* alpha_scale,
                                       int n, ScaledExponent& storage) {
  if (alpha_scale == nullptr || !ctx.plan.textures.alpha) return nullptr;
  // Lanes that all missed have powers of 0 either way: their exponents are not worth making.
  if (n == kLanes && all_lanes_negative(material)) return nullptr;
  const RenderSettings& r = ctx.scene->render;
  scale_exponents(exponents, material, alpha_scale, n, r.energy_normalize, r.model, storage);
  return &storage;
}

}  // namespace gloss

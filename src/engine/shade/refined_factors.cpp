// refine_pixel_factors (pixel_factors.h): the refined pixels of adaptive sampling summed like a
// uniform pixel of the same spp, so a refined pixel's factors equal uniform sampling's there.
#include <algorithm>

#include "engine/parallel_loops.h"
#include "engine/shade/pixel_groups.h"
#include "engine/shade/power_lanes.h"
#include "engine/shade/textured_factors.h"
#include "engine/simd/lanes.h"

namespace gloss {

namespace {
constexpr std::size_t kPixelsPerChunk = 256;  // refined pixels per parallel task
}  // namespace

bool refine_pixel_factors(const SampleCache& cache, const RenderContext& ctx, PixelFactors& out) {
  const RefinedSamples& refined = cache.refined;
  out.refined_pixel = refined.pixels;
  out.refined_weight.resize(refined.pixels.size());
  out.refined_background.resize(refined.pixels.size());
  out.extra_pixel.clear();
  out.extra_material.clear();
  out.extra_weight.clear();
  out.extra_diffuse.clear();
  out.extra_specular.clear();
  out.extra_textured.clear();
  out.refined_textured.clear();
  if (refined.spp == 0) return true;
  const Scene& scene = *ctx.scene;
  const std::size_t lights = ctx.plan.slots();
  const auto spp = static_cast<std::size_t>(refined.spp);
  const float inv_n = 1.0f / static_cast<float>(refined.spp);
  const MaterialExponents exponents = material_exponents(scene);
  const std::vector<std::int32_t> materials = object_materials(scene);
  const ShadingModel model = scene.render.model;
  const SamplePlane& plane = refined.plane;
  const bool textured = has_colour_texels(ctx.plan.textures);
  const int alpha_channel = ctx.plan.textures.alpha_channel();
  if (textured) {
    out.textured_stride = textured_stride(lights);
    out.refined_textured.resize(refined.pixels.size() * out.textured_stride);
  }
  const int chunks =
      static_cast<int>((refined.pixels.size() + kPixelsPerChunk - 1) / kPixelsPerChunk);
  std::vector<FactorExtras> extras(static_cast<std::size_t>(chunks));
  const bool done = parallel_chunks(chunks, ctx.cancel, [&](int chunk) {
    FactorExtras& chunk_extras = extras[static_cast<std::size_t>(chunk)];
    PixelGroups groups(lights, out.textured_stride);
    std::vector<float> texel(kMaxTexelChannels), diffuse(lights), sample_specular(lights);
    std::vector<std::int32_t> material(spp);
    std::vector<float> specular(spp * lights);  // [light * spp + sample]
    const std::size_t k0 = static_cast<std::size_t>(chunk) * kPixelsPerChunk;
    const std::size_t k1 = std::min(refined.pixels.size(), k0 + kPixelsPerChunk);
    for (std::size_t k = k0; k < k1; ++k) {
      const std::size_t e0 = k * spp;
      for (std::size_t s = 0; s < spp; ++s) {
        const std::int32_t object = plane.object[e0 + s];
        material[s] = object < 0 ? -1 : materials[static_cast<std::size_t>(object)];
      }
      for (std::size_t s0 = 0; s0 < spp; s0 += kLanes) {  // c^alpha by the lane helper
        const int m = static_cast<int>(std::min<std::size_t>(kLanes, spp - s0));
        ScaledExponent storage;  // once for every light of these samples
        const ScaledExponent* scaled = scaled_exponents(
            ctx, exponents, &material[s0],
            alpha_channel >= 0 ? plane.texels[alpha_channel].data() + e0 + s0 : nullptr, m,
            storage);
        for (std::size_t li = 0; li < lights; ++li) {
          const LightFactorPlane& f = plane.lights[li];
          alignas(64) float power[kLanes];
          if (scaled != nullptr) {
            scaled_power_lanes(exponents, &material[s0], f.cosine(model, e0 + s0), power, m,
                               scene.render.pow, *scaled);
          } else {
            specular_power_lanes(exponents, &material[s0], f.cosine(model, e0 + s0), power, m,
                                 scene.render.pow);
          }
          for (int i = 0; i < m; ++i) {
            specular[li * spp + s0 + i] = f.spec_weight[e0 + s0 + i] * power[i];
          }
        }
      }
      groups.clear();
      for (std::size_t s = 0; s < spp; ++s) {
        float* record = nullptr;
        float* acc = groups.add(material[s], textured ? &record : nullptr);
        if (acc == nullptr) continue;
        for (std::size_t li = 0; li < lights; ++li) {
          acc[2 * li] += plane.lights[li].diffuse_weight[e0 + s];
          acc[2 * li + 1] += specular[li * spp + s];
        }
        if (textured) {
          sample_texels(plane, e0 + s, texel.data(), diffuse.data());
          for (std::size_t li = 0; li < lights; ++li) sample_specular[li] = specular[li * spp + s];
          add_textured_sample(ctx.plan.textures, texel.data(), lights, diffuse.data(),
                              sample_specular.data(), record);
        }
      }
      groups.write(refined.pixels[k], inv_n, out, out.refined_weight[k], out.refined_background[k],
                   chunk_extras,
                   textured ? &out.refined_textured[k * out.textured_stride] : nullptr);
    }
  });
  if (!done) return false;
  for (const FactorExtras& e : extras) e.append_to(out);
  return true;
}

}  // namespace gloss

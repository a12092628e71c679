#include "engine/trace/single_sample_pass.h"

#include <algorithm>
#include <cstring>

#include "engine/shade/power_lanes.h"
#include "engine/shade/recombination.h"
#include "engine/shade/textured_factors.h"
#include "engine/shade/total_lanes.h"
#include "engine/simd/lane_store.h"
#include "engine/trace/sample_packet.h"
#include "shading/total.h"

namespace gloss {

namespace {
// Writes the packet's pixels (r, g, b each) to its row of image (clipped to the packet). The
// total is not read again by the pass, so a whole packet (192 bytes, 16-byte aligned in a
// std::vector of glm::vec3) is streamed past the caches; the sfence of for_each_packet orders it.
void store_pixels(const SamplePacket& packet, const float (&rgb)[3 * kLanes], Image& image) {
  float* row = &image.pixels[static_cast<std::size_t>(packet.y0) * image.width + packet.x0].x;
  const int n = packet.x1 - packet.x0;
  if (n == kLanes && stream_rgb_lanes(rgb, row)) return;
  std::memcpy(row, rgb, sizeof(float) * 3 * static_cast<std::size_t>(n));
}

// A pass over the packets of a cache holding one sample per pixel: sample(packet, on_light)
// fills plane 0 for the packet (tracing the hits or reusing them) and hands each planned
// light's lanes to on_light, which turns them into pixel factors on the spot (and, given a
// total image, into the total too).
template <class Sample>
bool fused_factors_pass(const SampleCache& cache, const RenderContext& ctx, PixelFactors& factors,
                        Image* total, Sample&& sample) {
  const Scene& scene = *ctx.scene;
  const std::size_t lights = ctx.plan.slots();
  const std::size_t pixels = cache.pixel_count();
  size_pixel_factors(factors, cache.width, cache.height, 1, lights);
  const MaterialExponents exponents = material_exponents(scene);
  const std::vector<std::int32_t> materials = object_materials(scene);
  const ShadingModel model = scene.render.model;
  const int width = cache.width;
  if (total != nullptr && (total->width != width || total->height != cache.height)) {
    *total = Image(width, cache.height);
  }
  const Recombination recombination(ctx);
  // With a total and an environment, the pass writes the sky too (factors.sky, one sample per
  // pixel: its own radiance, as environment_sky; kept for a later re-shade that turns the
  // background on) and, as the background, shows it where the lanes missed, as combine_terms
  // would (the same bits: total_under_sky with terms of 0, and + 0 on hits).
  const bool sky = total != nullptr && ctx.plan.sky;
  const bool shown = sky && recombination.sky_shown();
  const EnvironmentRotation<float> rotation =
      environment_rotation<float>(sky ? scene.environment.rotation : 0.0f);
  // Every pixel's sky is written by its packet below (0 on hits), so no fill first: at 1280x720
  // the fill was 11 MB on one thread before the parallel pass.
  if (sky && factors.sky.size() != pixels) factors.sky.resize(pixels);
  const float intensity = scene.environment.intensity;
  // Maps: the texel lanes multiply the total's terms as combine_terms multiplies a pixel's.
  const TexturePlan& maps = ctx.plan.textures;
  const bool mapped = has_colour_texels(maps);
  const int alpha_channel = maps.alpha_channel();
  const int term_channel[4] = {maps.ke_channel(), maps.ka_channel(), maps.kd_channel(),
                               maps.ks_channel()};
  return for_each_packet(cache, ctx, [&](SamplePacket& packet) {
    alignas(64) std::int32_t material[kLanes];
    alignas(64) float diffuse[kLanes], specular[kLanes];
    TexelLanes texels;
    TotalLanes totals(recombination);
    bool coverage = false;
    ScaledExponent storage;
    const ScaledExponent* scaled = nullptr;
    auto on_light = [&](std::size_t li, const LightLanes& lanes) {
      if (!coverage) {  // first light: the primary hits (and texels) are final by now
        single_sample_coverage(materials, packet.object, kLanes, material);
        // A shininess map's exponents, once for every light of the packet.
        scaled = scaled_exponents(ctx, exponents, material,
                                  alpha_channel >= 0 ? texels.channel[alpha_channel] : nullptr,
                                  kLanes, storage);
        coverage = true;
      }
      single_sample_light(exponents, scene.render.pow, material, lanes.diffuse_weight,
                          lanes.spec_weight,
                          model == ShadingModel::phong ? lanes.cos_phong : lanes.cos_blinn, kLanes,
                          diffuse, specular, scaled);
      stream_lanes(packet, width, diffuse, &factors.diffuse[li * pixels]);
      stream_lanes(packet, width, specular, &factors.specular[li * pixels]);
      if (total != nullptr) totals.add_light(material, li, diffuse, specular);
    };
    const long long rays = sample(packet, on_light, texels);
    if (!coverage) {
      single_sample_coverage(materials, packet.object, kLanes, material);
    }
    stream_lanes(packet, width, material, factors.material.data());
    if (total != nullptr) {
      float rgb[3 * kLanes];
      if (mapped) {
        const float* term_maps[4][3] = {};
        for (int t = 0; t < 4; ++t) {
          for (int c = 0; c < 3 && term_channel[t] >= 0; ++c) {
            term_maps[t][c] = texels.channel[term_channel[t] + c];
          }
        }
        totals.store(material, rgb, &term_maps);
      } else {
        totals.store(material, rgb);
      }
      if (sky) {
        glm::vec3* row = &factors.sky[static_cast<std::size_t>(packet.y0) * width + packet.x0];
        const int n = packet.x1 - packet.x0;
        bool missed = false;
        for (int i = 0; i < n; ++i) missed |= material[i] < 0;
        glm::vec3 radiance[kLanes];
        if (missed) sky_lanes(packet, scene.environment, rotation, radiance);
        for (int i = 0; i < n; ++i) {
          if (material[i] >= 0) {
            row[i] = glm::vec3(0.0f);
            continue;
          }
          row[i] = radiance[i];
          if (!shown) continue;
          for (int c = 0; c < 3; ++c) {
            rgb[3 * i + c] = form_total(0.0f, 0.0f, 0.0f, 0.0f, radiance[i][c] * intensity);
          }
        }
      }
      store_pixels(packet, rgb, *total);
    }
    return rays;
  });
}
}  // namespace

bool trace_single_sample(SampleCache& cache, const RenderContext& ctx, PixelFactors& factors,
                         Image* total) {
  drop_planes(cache, 0);  // the first sample of a fresh image (callers reset the cache)
  append_planes(cache, ctx.plan.plane_shape(), 1);
  const SamplePattern pattern = make_sample_pattern(cache.seed, cache.target_spp);
  const int stratum = sample_stratum(pattern, 0);
  const bool done = fused_factors_pass(
      cache, ctx, factors, total, [&](SamplePacket& packet, auto& on_light, TexelLanes& texels) {
        return trace_sample(packet, cache, ctx, pattern, stratum, cache.planes[0], on_light,
                            &texels);
      });
  if (!done) drop_planes(cache, 0);
  if (done) borrow_texels(cache.planes[0], ctx.plan, factors);
  return done;
}

bool trace_single_sample_at(SampleCache& strip, const SampleCache& image, const double* px,
                            const double* py, std::size_t n, const RenderContext& ctx,
                            PixelFactors& factors, Image* total) {
  strip.image_height = image.image_height;
  strip.row0 = 0;
  strip.target_spp = 1;  // centres
  strip.seed = image.seed;
  strip.camera = image.camera;
  strip.camera_d = image.camera_d;
  drop_planes(strip, 0);
  append_planes(strip, ctx.plan.plane_shape(), 1);
  const bool done = fused_factors_pass(
      strip, ctx, factors, total, [&](SamplePacket& packet, auto& on_light, TexelLanes& texels) {
        alignas(64) double x[kLanes], y[kLanes];
        const std::size_t first =
            static_cast<std::size_t>(packet.y0) * strip.width + static_cast<std::size_t>(packet.x0);
        for (int i = 0; i < kLanes; ++i) {
          const std::size_t k = std::min(first + static_cast<std::size_t>(i), n - 1);
          x[i] = px[k];
          y[i] = py[k];
        }
        packet_directions_at(packet, image, x, y);
        return trace_directed_sample(packet, strip, ctx, strip.width, strip.planes[0], on_light,
                                     &texels);
      });
  if (!done) drop_planes(strip, 0);
  return done;
}

bool relight_single_sample(SampleCache& cache, const RenderContext& ctx, PixelFactors& factors,
                           Image* total) {
  size_planes(cache, ctx.plan.plane_shape());
  const SamplePattern pattern = make_sample_pattern(cache.seed, cache.target_spp);
  const int stratum = sample_stratum(pattern, 0);
  const bool done = fused_factors_pass(
      cache, ctx, factors, total, [&](SamplePacket& packet, auto& on_light, TexelLanes& texels) {
        packet_directions(packet, cache, pattern, stratum);
        load_hits(packet, cache.width, cache.planes[0]);
        return shade_sample(packet, cache, ctx, cache.planes[0], on_light, &texels);
      });
  if (done) borrow_texels(cache.planes[0], ctx.plan, factors);
  return done;
}

}  // namespace gloss

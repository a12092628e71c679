#include "single_sample_pass.h"

#include "power_lanes.h"
#include "sample_packet.h"

namespace gloss {

bool trace_single_sample(SampleCache& cache, const RenderContext& ctx, PixelFactors& factors) {
  const Scene& scene = *ctx.scene;
  const std::size_t lights = ctx.plan.lights.size();
  const std::size_t pixels = cache.pixel_count();
  drop_planes(cache, 0);  // the first sample of a fresh image (callers reset the cache)
  append_planes(cache, lights, 1);
  size_pixel_factors(factors, cache.width, cache.height, 1, lights);
  const SamplePattern pattern = make_sample_pattern(cache.seed, cache.target_spp);
  const MaterialExponents exponents = material_exponents(scene);
  const std::vector<std::int32_t> materials = object_materials(scene);
  const ShadingModel model = scene.render.model;
  const int width = cache.width;
  const bool done = for_each_packet(cache, ctx, [&](SamplePacket& packet) {
    alignas(64) std::int32_t material[kPacketLanes];
    alignas(64) float diffuse[kPacketLanes], specular[kPacketLanes];
    bool coverage = false;
    auto on_light = [&](std::size_t li, const LightLanes& lanes) {
      if (!coverage) {  // first light: the primary hits are final by now
        single_sample_coverage(materials.data(), packet.object, kPacketLanes, material);
        coverage = true;
      }
      single_sample_light(exponents, scene.render.pow, material, lanes.diffuse_weight,
                          lanes.spec_weight,
                          model == ShadingModel::phong ? lanes.cos_phong : lanes.cos_blinn,
                          kPacketLanes, diffuse, specular);
      stream_lanes(packet, width, diffuse, &factors.diffuse[li * pixels]);
      stream_lanes(packet, width, specular, &factors.specular[li * pixels]);
    };
    const long long rays = trace_sample(packet, cache, ctx, pattern, sample_stratum(pattern, 0),
                                        cache.planes[0], on_light);
    if (!coverage) {
      single_sample_coverage(materials.data(), packet.object, kPacketLanes, material);
    }
    stream_lanes(packet, width, material, factors.material.data());
    return rays;
  });
  if (!done) drop_planes(cache, 0);
  return done;
}

}  // namespace gloss

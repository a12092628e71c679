#include "engine/environment/environment_stage.h"

#include <cstdint>
#include <vector>

#include "engine/environment/environment_taps.h"
#include "engine/environment/environment_uv_lanes.h"
#include "engine/parallel_loops.h"
#include "engine/adaptive/refined_samples.h"
#include "engine/trace/sample_packet.h"
#include "engine/trace/texture_lanes.h"
#include "shading/environment.h"

namespace gloss {

namespace {

// The environment's slots of one packet's lanes, stored in plane (width: the plane's row).
void store_environment(const SamplePacket& packet, const SampleCache& cache,
                       const RenderContext& ctx, int width, SamplePlane& plane) {
  LightLanes channels[3];
  if (!any_hit(packet)) {
    for (LightLanes& c : channels) c = LightLanes{};
  } else {
    SurfaceLanes surfaces;
    mapped_surfaces(packet, cache, ctx, plane, surfaces);  // normal maps included
    TexelLanes texels;  // the cached ones: a shininess map's alpha
    load_texels(packet, width, plane, texels);
    environment_lanes(packet, surfaces, ctx, alpha_lanes(ctx, texels), channels);
  }
  for (int c = 0; c < 3; ++c) {
    store_light(packet, width, channels[c], plane.lights[ctx.plan.environment_slot(c)]);
  }
}

}  // namespace

void sky_lanes(const SamplePacket& packet, const Environment& environment,
               const EnvironmentRotation<float>& rotation, glm::vec3 (&out)[kLanes]) {
  // The map-frame directions of every lane, then their map coordinates in one vector loop
  // (environment_uv_lanes.h: the scalar atan2f / acosf per missed lane cost as much as the rest).
  alignas(64) float mx[kLanes], my[kLanes], mz[kLanes], u[kLanes], t[kLanes];
  const float c = rotation.cos_a, sn = rotation.sin_a;
  for (int i = 0; i < kLanes; ++i) {  // masked-off lanes: +y, never read
    const bool on = packet.valid[i] != 0;
    const float dx = on ? static_cast<float>(packet.dir_x[i]) : 0.0f;
    const float dz = on ? static_cast<float>(packet.dir_z[i]) : 0.0f;
    mx[i] = dx * c - dz * sn;  // to_map_frame (shading/environment.h)
    my[i] = on ? static_cast<float>(packet.dir_y[i]) : 1.0f;
    mz[i] = dx * sn + dz * c;
  }
  map_uv_lanes(mx, my, mz, u, t);
  const Image& map = environment.map->radiance;
  alignas(64) std::int32_t width[kLanes], height[kLanes];
  for (int i = 0; i < kLanes; ++i) width[i] = map.width, height[i] = map.height;
  BilinearTaps taps;  // map_bilinear's, for all lanes at once (environment_taps.h)
  bilinear_taps(u, t, width, height, taps);
  for (int i = 0; i < kLanes; ++i) {
    out[i] = glm::vec3(0.0f);
    if (packet.valid[i] == 0 || packet.object[i] >= 0) continue;
    out[i] = bilinear_value(map.pixels.data(), taps, i);
  }
}

bool recompute_environment_factors(SampleCache& cache, const RenderContext& ctx) {
  if (!ctx.plan.environment) return true;
  const bool planes =
      visit_cached_samples(cache, ctx, [&](SamplePacket& packet, SamplePlane& plane) {
        store_environment(packet, cache, ctx, cache.width, plane);
        return 0LL;
      });
  if (!planes) return false;
  const int width = static_cast<int>(cache.refined.entries());
  return visit_refined_samples(cache, ctx, [&](SamplePacket& packet) {
    store_environment(packet, cache, ctx, width, cache.refined.plane);
    return 0LL;
  });
}

bool environment_sky(const SampleCache& cache, const RenderContext& ctx, PixelFactors& factors) {
  const Scene& scene = *ctx.scene;
  if (!ctx.plan.sky) {
    factors.sky.clear();
    return true;
  }
  const EnvironmentRotation<float> rotation =
      environment_rotation<float>(scene.environment.rotation);
  // No fill first (at 1280x720 an 11 MB one on one thread before the parallel pass): plane 0's
  // packets write every pixel (0 on hits, as 0 + its share would be), the later planes add.
  if (factors.sky.size() != cache.pixel_count()) factors.sky.resize(cache.pixel_count());
  const float share = 1.0f / static_cast<float>(std::max(1, cache.samples()));
  SampleCache& planes = const_cast<SampleCache&>(cache);  // visited read-only
  const SamplePlane* first = cache.planes.data();
  const bool done =
      visit_cached_samples(planes, ctx, [&](SamplePacket& packet, SamplePlane& plane) {
        glm::vec3 sky[kLanes];
        sky_lanes(packet, scene.environment, rotation, sky);
        glm::vec3* row =
            &factors.sky[static_cast<std::size_t>(packet.y0) * cache.width + packet.x0];
        const int n = packet.x1 - packet.x0;
        if (&plane == first) {
          for (int i = 0; i < n; ++i) row[i] = sky[i] * share;
        } else {
          for (int i = 0; i < n; ++i) row[i] += sky[i] * share;
        }
        return 0LL;
      });
  if (!done || cache.refined.spp == 0) return done;
  // Adaptive sampling's refined pixels: the mean over their own samples instead of the centre.
  const RefinedSamples& refined = cache.refined;
  std::vector<glm::vec3> entries(refined.entries());
  const bool traced = visit_refined_samples(cache, ctx, [&](SamplePacket& packet) {
    glm::vec3 sky[kLanes];
    sky_lanes(packet, scene.environment, rotation, sky);
    for (int i = 0; i < packet.x1 - packet.x0; ++i) {
      entries[static_cast<std::size_t>(packet.x0 + i)] = sky[i];
    }
    return 0LL;
  });
  if (!traced) return false;
  const float inv = 1.0f / static_cast<float>(refined.spp);
  for (std::size_t k = 0; k < refined.pixels.size(); ++k) {
    glm::vec3 sum(0.0f);
    for (int s = 0; s < refined.spp; ++s) sum += entries[k * refined.spp + s];
    factors.sky[refined.pixels[k]] = sum * inv;
  }
  return true;
}

}  // namespace gloss

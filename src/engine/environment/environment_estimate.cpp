#include "engine/environment/environment_estimate.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <embree3/rtcore.h>

#include "engine/adaptive/refined_samples.h"
#include "engine/environment/environment_sampling.h"
#include "engine/environment/scrambled_sobol.h"
#include "engine/simd/lane_mask.h"
#include "engine/trace/ray_packet.h"
#include "engine/trace/sample_packet.h"
#include "engine/trace/self_shadow.h"
#include "engine/trace/texture_lanes.h"
#include "shading/sampling.h"

namespace gloss {

namespace {

using Floats = float[EnvironmentEstimates::kFloats];

// The key of a sample's draws: its image pixel and which of the pixel's samples it is, so a
// band of gloss-cli's renderer and the editor's whole image draw the same directions.
std::uint32_t sample_key(std::uint32_t seed, int x, int y, int sample) {
  return mix_bits(seed ^ mix_bits(static_cast<std::uint32_t>(x) ^
                                  mix_bits(static_cast<std::uint32_t>(y) ^
                                           mix_bits(static_cast<std::uint32_t>(sample)))));
}

// `steps` steps for the packet's lanes (keys: each lane's sample_key), added to sums (lane i:
// sums + kFloats * i), then the lanes' estimates stored in the environment's slots of plane
// (width: the plane's row). Returns the shadow rays traced.
long long packet_steps(const SamplePacket& packet, const SampleCache& cache,
                       const RenderContext& ctx, const std::uint32_t (&keys)[kLanes],
                       int first_step, int steps, float* sums, int width, SamplePlane& plane) {
  long long rays = 0;
  const Scene& scene = *ctx.scene;
  const EnvironmentContext& env = ctx.environment;
  LightLanes out[3];
  for (LightLanes& c : out) c = LightLanes{};
  for (int c = 0; c < 3; ++c) {
    for (int i = 0; i < kLanes; ++i) out[c].cos_phong[i] = out[c].cos_blinn[i] = 1.0f;
  }
  if (any_hit(packet)) {
    SurfaceLanes surfaces;
    mapped_surfaces(packet, cache, ctx, plane, surfaces);  // normal maps included
    TexelLanes maps;
    load_texels(packet, width, plane, maps);
    const int alpha_map = ctx.plan.textures.alpha_channel();
    EnvironmentHit hits[kLanes];
    bool active[kLanes];
    Surface surface[kLanes];
    unsigned id[kLanes];
    for (int i = 0; i < kLanes; ++i) {
      active[i] = surfaces.hit[i] != 0 && packet.valid[i] != 0 && packet.object[i] >= 0;
      if (!active[i]) continue;
      const auto m =
          static_cast<std::size_t>(env.object_material[static_cast<std::size_t>(packet.object[i])]);
      const Surface s = surfaces.get(i);
      EnvironmentHit& h = hits[i];
      h.n = glm::normalize(glm::dvec3(s.n));
      h.v = glm::normalize(glm::dvec3(s.v));
      h.r = 2.0 * glm::dot(h.n, h.v) * h.n - h.v;
      h.alpha = scene.materials[m].shininess * (alpha_map >= 0 ? maps.channel[alpha_map][i] : 1.0f);
      h.model = scene.render.model;
      h.diffuse = env.diffuse[m] != 0;
      h.specular = env.specular[m] != 0;
      active[i] = h.diffuse || h.specular;
      surface[i] = s;
      id[i] = ctx.plan.spheres ? shadow_ray_id(scene, packet.object[i], s) : kNoOriginSphere;
    }
    StepNumbers numbers[kLanes];
    for (int i = 0; i < kLanes; ++i) {
      if (active[i]) numbers[i] = StepNumbers(keys[i]);
    }
    for (int k = first_step; k < first_step + steps; ++k) {
      EnvironmentDraws draws[kLanes];
      for (int i = 0; i < kLanes; ++i) {
        if (!active[i]) continue;
        double u[6];
        numbers[i].at(static_cast<std::uint32_t>(k), u);
        draws[i] = environment_draws(hits[i], scene.environment, env.rotation_d, *env.sampler, u);
      }
      bool visible[kLanes][EnvironmentDraws::kCount];
      for (int d = 0; d < EnvironmentDraws::kCount; ++d) {
        alignas(64) int lanes[kLanes];
        for (int i = 0; i < kLanes; ++i) lanes[i] = active[i] && draws[i].carries[d] ? -1 : 0;
        if (!scene.render.shadows) {
          for (int i = 0; i < kLanes; ++i) visible[i][d] = lanes[i] != 0;
          continue;
        }
        RTCRay16 ray;
        for (int i = 0; i < kLanes; ++i) {
          const glm::vec3 w(draws[i].w[d]);
          set_packet_ray(ray, i, shadow_ray_origin(surface[i], packet.t[i], w), w);
          ray.id[i] = id[i];
        }
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);  // incoherent: every lane its own way
        rays += count_set_lanes(lanes);
        rtcOccluded16(lanes, ctx.embree->handle(), &context, &ray);
        for (int i = 0; i < kLanes; ++i) {
          visible[i][d] = lanes[i] != 0 && ray.tfar[i] != -std::numeric_limits<float>::infinity();
        }
      }
      for (int i = 0; i < kLanes; ++i) {
        if (!active[i]) continue;
        float* s = sums + EnvironmentEstimates::kFloats * i;
        for (int d = 0; d < EnvironmentDraws::kCount; ++d) {
          if (visible[i][d]) {
            for (int c = 0; c < 3; ++c) {
              s[c] += static_cast<float>(draws[i].diffuse[d][c]);
              s[4 + c] += static_cast<float>(draws[i].specular[d][c]);
            }
          }
          s[3] += static_cast<float>(draws[i].diffuse_norm[d]);
          s[7] += static_cast<float>(draws[i].specular_norm[d]);
        }
      }
    }
    for (int i = 0; i < kLanes; ++i) {
      if (!active[i]) continue;
      const float* s = sums + EnvironmentEstimates::kFloats * i;
      for (int c = 0; c < 3; ++c) {
        out[c].diffuse_weight[i] = s[3] > 0.0f ? s[c] / s[3] : 0.0f;
        out[c].spec_weight[i] = s[7] > 0.0f ? s[4 + c] / s[7] : 0.0f;
      }
    }
  }
  for (int c = 0; c < 3; ++c) {
    store_light(packet, width, out[c], plane.lights[ctx.plan.environment_slot(c)]);
  }
  return rays;
}

}  // namespace

std::uint64_t EnvironmentEstimates::bytes() const {
  std::uint64_t total = refined.size() * sizeof(float);
  for (const auto& p : planes) total += p.size() * sizeof(float);
  return total;
}

int next_environment_steps(const RenderContext& ctx, const EnvironmentEstimates& estimates) {
  if (!ctx.plan.environment || ctx.environment.sampler == nullptr) return 0;
  const int target = ctx.scene->render.env_samples;
  if (estimates.steps >= target) return 0;
  const int next = estimates.steps == 0 ? 16 : estimates.steps;
  return std::min(next, target - estimates.steps);
}

bool add_environment_steps(SampleCache& cache, const RenderContext& ctx,
                           EnvironmentEstimates& estimates, int steps) {
  if (!ctx.plan.environment || ctx.environment.sampler == nullptr || steps <= 0) return true;
  const std::size_t per_plane = cache.pixel_count() * EnvironmentEstimates::kFloats;
  if (estimates.steps == 0) {
    estimates.planes.assign(static_cast<std::size_t>(cache.samples()),
                            std::vector<float>(per_plane, 0.0f));
    estimates.refined.assign(cache.refined.entries() * EnvironmentEstimates::kFloats, 0.0f);
  }
  const int first = estimates.steps;
  const std::uint32_t seed = mix_bits(ctx.scene->render.seed ^ 0x5bd1e995U);
  const bool planes =
      visit_cached_samples(cache, ctx, [&](SamplePacket& packet, SamplePlane& plane) {
        const auto s = static_cast<std::size_t>(&plane - cache.planes.data());
        float* sums = estimates.planes[s].data() +
                      (static_cast<std::size_t>(packet.y0) * cache.width + packet.x0) *
                          EnvironmentEstimates::kFloats;
        std::uint32_t keys[kLanes];
        for (int i = 0; i < kLanes; ++i) {
          keys[i] = sample_key(seed, packet.x0 + i, packet.y0 + cache.row0, static_cast<int>(s));
        }
        return packet_steps(packet, cache, ctx, keys, first, steps, sums, cache.width, plane);
      });
  if (!planes) return false;
  const int width = static_cast<int>(cache.refined.entries());
  const bool refined = visit_refined_samples(cache, ctx, [&](SamplePacket& packet) {
    float* sums = estimates.refined.data() +
                  static_cast<std::size_t>(packet.x0) * EnvironmentEstimates::kFloats;
    // Entry e is sample e mod spp of refined pixel e / spp (after the centres' plane 0).
    const RefinedSamples& refined = cache.refined;
    std::uint32_t keys[kLanes];
    for (int i = 0; i < kLanes; ++i) {
      const std::size_t e =
          std::min(static_cast<std::size_t>(packet.x0 + i), refined.entries() - 1);
      const std::uint32_t pixel = refined.pixels[e / static_cast<std::size_t>(refined.spp)];
      const int x = static_cast<int>(pixel % static_cast<std::uint32_t>(cache.width));
      const int y = static_cast<int>(pixel / static_cast<std::uint32_t>(cache.width)) + cache.row0;
      keys[i] =
          sample_key(seed, x, y, 1 + static_cast<int>(e % static_cast<std::size_t>(refined.spp)));
    }
    return packet_steps(packet, cache, ctx, keys, first, steps, sums, width, cache.refined.plane);
  });
  if (!refined) return false;
  estimates.steps += steps;
  return true;
}

}  // namespace gloss

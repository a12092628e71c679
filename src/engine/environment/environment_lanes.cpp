// environment_lanes (trace/sample_packet.h): the environment's fast path for the 16 lanes of a
// packet, from the prefiltered levels (prefiltered_environment.h).
#include <cstdint>

#include "engine/environment/prefiltered_environment.h"
#include "engine/trace/sample_packet.h"
#include "shading/environment.h"

namespace gloss {

void environment_lanes(const SamplePacket& packet, const SurfaceLanes& surfaces,
                       const RenderContext& ctx, LightLanes (&out)[3]) {
  const EnvironmentContext& env = ctx.environment;
  const PrefilteredEnvironment& maps = *env.maps;
  for (int i = 0; i < kLanes; ++i) {
    glm::vec3 diffuse(0.0f), specular(0.0f);
    const std::int32_t object = packet.object[i];
    if (surfaces.hit[i] != 0 && object >= 0) {
      const auto m = static_cast<std::size_t>(env.object_material[static_cast<std::size_t>(object)]);
      const glm::vec3 n(surfaces.nx[i], surfaces.ny[i], surfaces.nz[i]);
      if (env.diffuse[m] != 0) diffuse = maps.diffuse(to_map_frame(n, env.rotation));
      if (env.specular[m] != 0) {
        const glm::vec3 v(surfaces.vx[i], surfaces.vy[i], surfaces.vz[i]);
        const glm::vec3 r = 2.0f * glm::dot(n, v) * n - v;
        specular = maps.specular(env.exponent[m], to_map_frame(glm::normalize(r), env.rotation));
      }
    }
    for (int c = 0; c < 3; ++c) {
      out[c].diffuse_weight[i] = diffuse[c];
      out[c].spec_weight[i] = specular[c];
      out[c].cos_phong[i] = 1.0f;
      out[c].cos_blinn[i] = 1.0f;
    }
  }
}

}  // namespace gloss

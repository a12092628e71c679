// environment_lanes (trace/sample_packet.h): the environment's fast path for the 16 lanes of a
// packet, from the prefiltered levels (prefiltered_environment.h).
#include <cmath>
#include <cstdint>

#include "engine/environment/environment_uv_lanes.h"
#include "engine/environment/prefiltered_environment.h"
#include "engine/trace/sample_packet.h"
#include "shading/environment.h"

namespace gloss {

namespace {

// The map-frame normals and mirror directions of every lane, and their map coordinates. In
// vector loops over all lanes (misses included, with a harmless +y in place of their normal):
// the per-lane scalar atan2f / acosf these replace were most of the fast path's cost.
struct LaneDirections {
  alignas(64) float nx[kLanes], ny[kLanes], nz[kLanes];
  alignas(64) float rx[kLanes], ry[kLanes], rz[kLanes];
  alignas(64) float nu[kLanes], nt[kLanes], ru[kLanes], rt[kLanes];
};

void lane_directions(const SurfaceLanes& s, const EnvironmentRotation<float>& rot,
                     LaneDirections& d) {
  const float c = rot.cos_a, sn = rot.sin_a;
#pragma omp simd
  for (int i = 0; i < kLanes; ++i) {
    const bool hit = s.hit[i] != 0;
    const float nx = hit ? s.nx[i] : 0.0f, ny = hit ? s.ny[i] : 1.0f, nz = hit ? s.nz[i] : 0.0f;
    const float vx = hit ? s.vx[i] : 0.0f, vy = hit ? s.vy[i] : 1.0f, vz = hit ? s.vz[i] : 0.0f;
    // r = 2 (n.v) n - v, normalised (n and v are unit up to rounding), as the scalar path did.
    const float k = 2.0f * (nx * vx + ny * vy + nz * vz);
    float rx = k * nx - vx, ry = k * ny - vy, rz = k * nz - vz;
    const float inv = 1.0f / std::sqrt(rx * rx + ry * ry + rz * rz);
    rx *= inv, ry *= inv, rz *= inv;
    // to_map_frame (shading/environment.h): turned by -rotation about +y.
    d.nx[i] = nx * c - nz * sn, d.ny[i] = ny, d.nz[i] = nx * sn + nz * c;
    d.rx[i] = rx * c - rz * sn, d.ry[i] = ry, d.rz[i] = rx * sn + rz * c;
  }
  map_uv_lanes(d.nx, d.ny, d.nz, d.nu, d.nt);
  map_uv_lanes(d.rx, d.ry, d.rz, d.ru, d.rt);
}

}  // namespace

void environment_lanes(const SamplePacket& packet, const SurfaceLanes& surfaces,
                       const RenderContext& ctx, LightLanes (&out)[3]) {
  const EnvironmentContext& env = ctx.environment;
  const PrefilteredEnvironment& maps = *env.maps;
  LaneDirections d;
  lane_directions(surfaces, env.rotation, d);
  for (int i = 0; i < kLanes; ++i) {
    glm::vec3 diffuse(0.0f), specular(0.0f);
    const std::int32_t object = packet.object[i];
    if (surfaces.hit[i] != 0 && object >= 0) {
      const auto m =
          static_cast<std::size_t>(env.object_material[static_cast<std::size_t>(object)]);
      if (env.diffuse[m] != 0) diffuse = maps.diffuse_at(d.nu[i], d.nt[i]);
      if (env.specular[m] != 0) specular = maps.specular_at(env.blend[m], d.ru[i], d.rt[i]);
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

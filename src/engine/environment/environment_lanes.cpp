// environment_lanes (trace/sample_packet.h): the environment's fast path for the 16 lanes of a
// packet, from the prefiltered levels (prefiltered_environment.h).
#include <cassert>
#include <cmath>
#include <cstdint>

#include "engine/environment/environment_taps.h"
#include "engine/environment/environment_uv_lanes.h"
#include "engine/environment/prefiltered_environment.h"
#include "engine/trace/sample_packet.h"
#include "shading/environment.h"

namespace gloss {

namespace {

// Exponents 0 and 1, 2, 4 ... kTopPrefilteredExponent, then the map: 13 images today.
constexpr int kMaxImages = 32;
static_assert(kTopPrefilteredExponent <= float(1 << 29), "more levels than kMaxImages");

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
                       const RenderContext& ctx, const float* alpha_scale, LightLanes (&out)[3]) {
  const EnvironmentContext& env = ctx.environment;
  const PrefilteredEnvironment& maps = *env.maps;
  LaneDirections d;
  lane_directions(surfaces, env.rotation, d);
  // Per lane its material's terms and levels (lanes without a specular term read level 1, as
  // the diffuse term: valid taps, never used). The levels' images are looked up once per packet.
  const int images = maps.levels() + 1;  // the levels, then the map itself
  assert(images <= kMaxImages);
  const Image* level_image[kMaxImages];
  for (int k = 0; k < images; ++k) level_image[k] = &maps.image(k);
  alignas(64) std::int32_t diffuse_on[kLanes], level_a[kLanes], level_b[kLanes];
  alignas(64) std::int32_t dw[kLanes], dh[kLanes], aw[kLanes], ah[kLanes], bw[kLanes], bh[kLanes];
  alignas(64) float wb[kLanes];
  const Image& diffuse_level = *level_image[1];
  bool any_diffuse = false, any_a = false, any_b = false;
  for (int i = 0; i < kLanes; ++i) {
    const std::int32_t object = packet.object[i];
    diffuse_on[i] = 0;
    level_a[i] = level_b[i] = -1;
    wb[i] = 0.0f;
    if (surfaces.hit[i] != 0 && object >= 0) {
      const auto m =
          static_cast<std::size_t>(env.object_material[static_cast<std::size_t>(object)]);
      diffuse_on[i] = env.diffuse[m];
      any_diffuse |= diffuse_on[i] != 0;
      if (env.specular[m] != 0) {
        // A shininess map scales the material's alpha per lane: the lobe's levels are the
        // lane's (the material's table entry where the map gives 1).
        const bool scaled = alpha_scale != nullptr && alpha_scale[i] != 1.0f;
        const LevelBlend b =
            scaled
                ? maps.blend(phong_equivalent_exponent(
                      ctx.scene->render.model, ctx.scene->materials[m].shininess * alpha_scale[i]))
                : env.blend[m];
        level_a[i] = b.a;
        any_a = true;
        if (b.wb != 0.0f) {  // one level (or the map) alone: no second read
          level_b[i] = b.b;
          wb[i] = b.wb;
          any_b = true;
        }
      }
    }
    const Image& a = *level_image[level_a[i] < 0 ? 1 : level_a[i]];
    const Image& b = *level_image[level_b[i] < 0 ? 1 : level_b[i]];
    dw[i] = diffuse_level.width, dh[i] = diffuse_level.height;
    aw[i] = a.width, ah[i] = a.height, bw[i] = b.width, bh[i] = b.height;
  }
  // Taps only for the reads some lane makes (a packet of floor or of one metal needs one kind).
  BilinearTaps diffuse_taps, a_taps, b_taps;
  if (any_diffuse) bilinear_taps(d.nu, d.nt, dw, dh, diffuse_taps);
  if (any_a) bilinear_taps(d.ru, d.rt, aw, ah, a_taps);
  if (any_b) bilinear_taps(d.ru, d.rt, bw, bh, b_taps);
  for (int i = 0; i < kLanes; ++i) {
    glm::vec3 diffuse(0.0f), specular(0.0f);
    if (diffuse_on[i] != 0) diffuse = bilinear_value(diffuse_level.pixels.data(), diffuse_taps, i);
    if (level_a[i] >= 0) {  // PrefilteredEnvironment::specular_at, the same blend
      specular = bilinear_value(level_image[level_a[i]]->pixels.data(), a_taps, i);
      if (level_b[i] >= 0) {
        const glm::vec3 lb = bilinear_value(level_image[level_b[i]]->pixels.data(), b_taps, i);
        specular = specular + (lb - specular) * wb[i];
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

#include "engine/trace/normal_map_lanes.h"

#include <cmath>
#include <limits>

#include "engine/trace/sample_packet.h"

namespace gloss {

namespace {

// glm::length's and glm::normalize's arithmetic on components: sqrt(x x + y y + z z), and the
// vector times 1 / sqrt of it.
inline float length3(float x, float y, float z) {
  return std::sqrt(x * x + y * y + z * z);
}
inline float inverse_length3(float x, float y, float z) {
  return 1.0f / std::sqrt(x * x + y * y + z * z);
}
// len > 0 and finite (len is a square root: at least 0, or NaN), as an int: GCC's vectoriser
// takes selects on an int compared with 0, not on a bool made of && (docs/engine.md, "Maps
// in lanes").
inline int usable(float len) {
  return static_cast<int>(len > 0.0f) & static_cast<int>(len <= std::numeric_limits<float>::max());
}

}  // namespace

void normal_map_lanes(const Material& material, const TextureMap& map, const TangentLanes& frames,
                      const float (&texel)[4][kLanes], std::uint32_t mask, SurfaceLanes& surfaces) {
  const float scale = material.normal_scale;
  // A map turned or mirrored in (u, v) turns its tangent-space x and y back (normal_map_normal).
  const bool turned = map.rotation != 0.0f || map.scale.x < 0.0f || map.scale.y < 0.0f;
  const float angle = -map.rotation * 3.14159265358979323846f / 180.0f;
  const float c = turned ? std::cos(angle) : 1.0f, s = turned ? std::sin(angle) : 0.0f;
  const float mirror_x = map.scale.x < 0.0f ? -1.0f : 1.0f;
  const float mirror_y = map.scale.y < 0.0f ? -1.0f : 1.0f;
#pragma omp simd
  for (int i = 0; i < kLanes; ++i) {
    // tangent_space_normal: 2 c - 1, x and y times the scale, normalised; (0, 0, 1) where that
    // leaves nothing to normalise.
    float mx = (2.0f * texel[0][i] - 1.0f) * scale, my = (2.0f * texel[1][i] - 1.0f) * scale,
          mz = 2.0f * texel[2][i] - 1.0f;
    const float m_len = length3(mx, my, mz);
    const int m_ok = usable(m_len);
    mx = m_ok != 0 ? mx / m_len : 0.0f;
    my = m_ok != 0 ? my / m_len : 0.0f;
    mz = m_ok != 0 ? mz / m_len : 1.0f;
    // Unturned (c = 1, s = 0, no mirror) this leaves mx and my equal to what they were (a -0 may
    // become +0, which only `!=` below sees, and it sees them equal); a select on
    // the loop-invariant `turned` would keep GCC from vectorising the loop.
    const float x = c * mx - s * my, y = s * mx + c * my;
    mx = mirror_x * x;
    my = mirror_y * y;
    // N: the surface's own orientation.
    const float side = frames.side[i];
    const float nx = side * surfaces.nx[i], ny = side * surfaces.ny[i], nz = side * surfaces.nz[i];
    // orthogonal_tangent: Gram-Schmidt, or any_perpendicular where the tangent has no part
    // across N.
    const float d = nx * frames.tx[i] + ny * frames.ty[i] + nz * frames.tz[i];
    float tx = frames.tx[i] - nx * d, ty = frames.ty[i] - ny * d, tz = frames.tz[i] - nz * d;
    const float t_len = length3(tx, ty, tz);
    const int gram_schmidt = static_cast<int>(t_len > 1e-12f) &
                             static_cast<int>(t_len <= std::numeric_limits<float>::max());
    const bool x_axis = std::fabs(nx) < 0.9f;  // cross((1, 0, 0), N) or cross((0, 1, 0), N)
    const float ax = x_axis ? 0.0f : nz, ay = x_axis ? -nz : 0.0f, az = x_axis ? ny : -nx;
    const float r = inverse_length3(ax, ay, az);
    tx = gram_schmidt != 0 ? tx / t_len : ax * r;
    ty = gram_schmidt != 0 ? ty / t_len : ay * r;
    tz = gram_schmidt != 0 ? tz / t_len : az * r;
    // normal_from_map: B = w cross(N, T), n = T x + B y + N z, normalised (N where it cannot be).
    const float w = frames.handedness[i];
    const float bx = w * (ny * tz - ty * nz), by = w * (nz * tx - tz * nx),
                bz = w * (nx * ty - tx * ny);
    float ox = tx * mx + bx * my + nx * mz, oy = ty * mx + by * my + ny * mz,
          oz = tz * mx + bz * my + nz * mz;
    const float o_len = length3(ox, oy, oz);
    const int o_ok = usable(o_len);
    ox = o_ok != 0 ? ox / o_len : nx;
    oy = o_ok != 0 ? oy / o_len : ny;
    oz = o_ok != 0 ? oz / o_len : nz;
    // map_values keeps the normal where the map left it as it was; else the horizon rule
    // (facing_viewer) on the viewer's side.
    const int moved =
        static_cast<int>(ox != nx) | static_cast<int>(oy != ny) | static_cast<int>(oz != nz);
    const float fx = side * ox, fy = side * oy, fz = side * oz;
    const float vx = surfaces.vx[i], vy = surfaces.vy[i], vz = surfaces.vz[i];
    const float dv = fx * vx + fy * vy + fz * vz;
    const float hx = fx - 2.0f * dv * vx, hy = fy - 2.0f * dv * vy, hz = fz - 2.0f * dv * vz;
    const float hr = inverse_length3(hx, hy, hz);
    const int write = static_cast<int>((mask >> i) & 1u) & moved;
    surfaces.nx[i] = write != 0 ? (dv < 0.0f ? hx * hr : fx) : surfaces.nx[i];
    surfaces.ny[i] = write != 0 ? (dv < 0.0f ? hy * hr : fy) : surfaces.ny[i];
    surfaces.nz[i] = write != 0 ? (dv < 0.0f ? hz * hr : fz) : surfaces.nz[i];
  }
}

}  // namespace gloss

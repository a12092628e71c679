#pragma once
// Looking a texture up (docs/spec/shading.md, "Textures"): bilinear between the four nearest
// texel centres of one level, trilinear between the two levels around a footprint's level
// (footprint.h), or the nearest texel (a measured knob). Templates over the scalar type: the
// renderer computes in float, the reference path in double; the texels are float either way.
// The weights are the contract's: texel (i, j) has its centre at u = (i + 0.5) / W,
// v = 1 - (j + 0.5) / H, so x = u W - 0.5 and y = (1 - v) H - 0.5 are texel coordinates whose
// integer points are centres, and the weights of (floor(x), floor(x) + 1) are (1 - fx, fx).
#include <cmath>
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "texture/texture.h"

namespace gloss {

// How a sample reads a map: the contract's trilinear filtering, or a cheaper knob.
enum class MapFilter : std::uint8_t {
  trilinear,  // bilinear at the two levels around the footprint's, blended (the contract)
  bilinear,   // bilinear at level 0 whatever the footprint (aliases when minified)
  nearest,    // the texel under the point at level 0 (blocky when magnified, aliases minified)
};

// "trilinear" / "bilinear" / "nearest".
const char* to_string(MapFilter filter);

// Texel index i of a side of n texels, for any i (after coordinate_range, |i| <= 2n + 1).
inline int wrap_index(int i, int n, Wrap wrap) {
  // The common cases first, without a division (an integer division costs ~25 cycles, and a
  // bilinear lookup wraps four indices): an index on the side, and repeat's one step past
  // either edge, all that coordinate_range leaves it (u in [0, 1) gives floor(u W - 0.5) in
  // [-1, W - 1], and the neighbour one more).
  if (i >= 0 && i < n) return i;  // every mode
  if (wrap == Wrap::repeat) {
    if (i == -1) return n - 1;
    if (i == n) return 0;
  }
  switch (wrap) {
    case Wrap::clamp:
      return i < 0 ? 0 : (i >= n ? n - 1 : i);
    case Wrap::mirror: {
      const int period = 2 * n;
      int m = i % period;
      m = m < 0 ? m + period : m;
      return m < n ? m : period - 1 - m;
    }
    case Wrap::repeat:
      break;
  }
  const int m = i % n;
  return m < 0 ? m + n : m;
}

// A coordinate brought into one period of its wrap mode without changing any lookup: repeat
// [0, 1), mirror [0, 2), clamp [-1, 2]. Large coordinates (1e6) then make small texel indices.
template <class T>
T coordinate_range(T c, Wrap wrap) {
  switch (wrap) {
    case Wrap::clamp:
      return c < T(-1) ? T(-1) : (c > T(2) ? T(2) : c);
    case Wrap::mirror:
      return c - T(2) * std::floor(c / T(2));
    case Wrap::repeat:
      break;
  }
  return c - std::floor(c);
}

// Texel (i, j) of a level (indices already wrapped) as (r, g, b, a); one-channel maps as
// (g, g, g, 1).
template <class T>
glm::vec<4, T> texel_at(const Texture& texture, int level, int i, int j) {
  const MipLevel& l = texture.levels[static_cast<std::size_t>(level)];
  const std::size_t k = static_cast<std::size_t>(j) * l.width + i;
  if (texture.channels == 1) {
    const T g = static_cast<T>(l.texels[k]);
    return {g, g, g, T(1)};
  }
  const float* t = &l.texels[k * 4];
  return {static_cast<T>(t[0]), static_cast<T>(t[1]), static_cast<T>(t[2]), static_cast<T>(t[3])};
}

// The texel coordinates of (u, v) on a level of w x h: x = u w - 0.5, y = (1 - v) h - 0.5.
template <class T>
glm::vec<2, T> texel_coordinates(T u, T v, int w, int h, Wrap wrap_u, Wrap wrap_v) {
  T cu = coordinate_range(u, wrap_u), cv = coordinate_range(v, wrap_v);
  cu = std::isfinite(cu) ? cu : T(0);  // a non-finite coordinate reads the first texel
  cv = std::isfinite(cv) ? cv : T(0);
  return {cu * static_cast<T>(w) - T(0.5), (T(1) - cv) * static_cast<T>(h) - T(0.5)};
}

template <class T>
glm::vec<4, T> bilinear(const Texture& texture, int level, T u, T v, Wrap wrap_u, Wrap wrap_v) {
  const MipLevel& l = texture.levels[static_cast<std::size_t>(level)];
  const glm::vec<2, T> xy = texel_coordinates(u, v, l.width, l.height, wrap_u, wrap_v);
  const T fx0 = std::floor(xy.x), fy0 = std::floor(xy.y);
  const T fx = xy.x - fx0, fy = xy.y - fy0;
  const int x0 = static_cast<int>(fx0), y0 = static_cast<int>(fy0);
  const int i0 = wrap_index(x0, l.width, wrap_u), i1 = wrap_index(x0 + 1, l.width, wrap_u);
  const int j0 = wrap_index(y0, l.height, wrap_v), j1 = wrap_index(y0 + 1, l.height, wrap_v);
  const std::size_t row0 = static_cast<std::size_t>(j0) * l.width;
  const std::size_t row1 = static_cast<std::size_t>(j1) * l.width;
  const float* texels = l.texels.data();
  if (texture.channels == 1) {
    const T g =
        (static_cast<T>(texels[row0 + i0]) * (T(1) - fx) + static_cast<T>(texels[row0 + i1]) * fx) *
            (T(1) - fy) +
        (static_cast<T>(texels[row1 + i0]) * (T(1) - fx) + static_cast<T>(texels[row1 + i1]) * fx) *
            fy;
    return {g, g, g, T(1)};
  }
  // The four texels straight from the level's array (texel_at per texel re-read the level).
  auto at = [&](std::size_t k) {
    const float* t = texels + k * 4;
    return glm::vec<4, T>(static_cast<T>(t[0]), static_cast<T>(t[1]), static_cast<T>(t[2]),
                          static_cast<T>(t[3]));
  };
  // The contract's order of operations (and the GLSL's): along x in each row, then along y.
  const glm::vec<4, T> top = at(row0 + i0) * (T(1) - fx) + at(row0 + i1) * fx;
  const glm::vec<4, T> bottom = at(row1 + i0) * (T(1) - fx) + at(row1 + i1) * fx;
  return top * (T(1) - fy) + bottom * fy;
}

template <class T>
glm::vec<4, T> nearest(const Texture& texture, int level, T u, T v, Wrap wrap_u, Wrap wrap_v) {
  const MipLevel& l = texture.levels[static_cast<std::size_t>(level)];
  const glm::vec<2, T> xy = texel_coordinates(u, v, l.width, l.height, wrap_u, wrap_v);
  // The texel whose square holds the point: its centre is the nearest.
  const int i = wrap_index(static_cast<int>(std::floor(xy.x + T(0.5))), l.width, wrap_u);
  const int j = wrap_index(static_cast<int>(std::floor(xy.y + T(0.5))), l.height, wrap_v);
  return texel_at<T>(texture, level, i, j);
}

// The level a lookup at footprint level `lod` reads (footprint.h): clamped to the pyramid.
template <class T>
T clamp_level(const Texture& texture, T lod) {
  const T top = static_cast<T>(texture.level_count() - 1);
  return lod > T(0) ? (lod < top ? lod : top) : T(0);  // NaN reads level 0
}

template <class T>
glm::vec<4, T> trilinear(const Texture& texture, T lod, T u, T v, Wrap wrap_u, Wrap wrap_v) {
  const T level = clamp_level(texture, lod);
  const int l0 = static_cast<int>(std::floor(level));
  const T f = level - static_cast<T>(l0);
  const glm::vec<4, T> a = bilinear(texture, l0, u, v, wrap_u, wrap_v);
  if (!(f > T(0))) return a;
  const glm::vec<4, T> b = bilinear(texture, l0 + 1, u, v, wrap_u, wrap_v);
  return a * (T(1) - f) + b * f;
}

// A lookup by filter: trilinear at lod, or one of the knobs at level 0.
template <class T>
glm::vec<4, T> sample_texture(const Texture& texture, MapFilter filter, T lod, T u, T v,
                              Wrap wrap_u, Wrap wrap_v) {
  switch (filter) {
    case MapFilter::bilinear:
      return bilinear(texture, 0, u, v, wrap_u, wrap_v);
    case MapFilter::nearest:
      return nearest(texture, 0, u, v, wrap_u, wrap_v);
    case MapFilter::trilinear:
      break;
  }
  return trilinear(texture, lod, u, v, wrap_u, wrap_v);
}

}  // namespace gloss

#include "engine/trace/map_lanes.h"

#include <cmath>
#include <cstddef>

#include <glm/vec4.hpp>

#include "texture/footprint.h"

namespace gloss {

namespace {

// The levels a pyramid can have: a side of at most 2^31 texels halves to 1 in 32 steps.
constexpr int kMaxLevels = 32;

// texture_lookup.h's coordinate_range and wrap_index for one wrap mode, as selects a loop over
// lanes vectorises. coordinate_range leaves repeat in [0, 1], mirror in [0, 2] and clamp in
// [-1, 2], so a level of n texels gives column (or row) indices in [-1, n] (repeat), [-1, 2 n]
// (mirror) or [-n - 1, 2 n] (clamp): the ranges the selects below cover, where wrap_index
// needs its remainders only for indices further out.
template <Wrap W>
float lane_range(float c) {
  if (W == Wrap::clamp) return c < -1.0f ? -1.0f : (c > 2.0f ? 2.0f : c);
  if (W == Wrap::mirror) return c - 2.0f * std::floor(c / 2.0f);
  return c - std::floor(c);
}
template <Wrap W>
std::int32_t lane_wrap(std::int32_t i, std::int32_t n) {
  if (W == Wrap::clamp) return i < 0 ? 0 : (i >= n ? n - 1 : i);
  if (W == Wrap::mirror) {
    const std::int32_t m = i < 0 ? i + 2 * n : (i >= 2 * n ? i - 2 * n : i);
    return m < n ? m : 2 * n - 1 - m;
  }
  return i < 0 ? i + n : (i >= n ? i - n : i);
}

// The taps of the lanes at map coordinates (cu, cv) (already in their wrap's range) on the level
// of each lane: texel_coordinates and bilinear's index arithmetic.
template <Wrap WU, Wrap WV>
void level_taps(const float* cu, const float* cv, const std::int32_t* widths,
                const std::int32_t* heights, LevelTaps& taps) {
#pragma omp simd
  for (int i = 0; i < kLanes; ++i) {
    const std::int32_t w = widths[taps.level[i]], h = heights[taps.level[i]];
    const float x = cu[i] * static_cast<float>(w) - 0.5f;
    const float y = (1.0f - cv[i]) * static_cast<float>(h) - 0.5f;
    const float fx0 = std::floor(x), fy0 = std::floor(y);
    taps.fx[i] = x - fx0;
    taps.fy[i] = y - fy0;
    const std::int32_t x0 = static_cast<std::int32_t>(fx0), y0 = static_cast<std::int32_t>(fy0);
    const std::int32_t i0 = lane_wrap<WU>(x0, w), i1 = lane_wrap<WU>(x0 + 1, w);
    const std::int32_t row0 = lane_wrap<WV>(y0, h) * w, row1 = lane_wrap<WV>(y0 + 1, h) * w;
    taps.t00[i] = row0 + i0;
    taps.t10[i] = row0 + i1;
    taps.t01[i] = row1 + i0;
    taps.t11[i] = row1 + i1;
  }
}

// Lane i's bilinear value at its taps (bilinear's blend: along x in each row, then along y).
glm::vec4 blend(const Texture& texture, const LevelTaps& taps, int i) {
  const float* texels = texture.levels[static_cast<std::size_t>(taps.level[i])].texels.data();
  const float fx = taps.fx[i], fy = taps.fy[i];
  auto offset = [](std::int32_t t) { return static_cast<std::size_t>(t); };
  if (texture.channels == 1) {
    const float g =
        (texels[offset(taps.t00[i])] * (1.0f - fx) + texels[offset(taps.t10[i])] * fx) *
            (1.0f - fy) +
        (texels[offset(taps.t01[i])] * (1.0f - fx) + texels[offset(taps.t11[i])] * fx) * fy;
    return {g, g, g, 1.0f};
  }
  auto at = [&](std::int32_t t) {
    const float* p = texels + offset(t) * 4;
    return glm::vec4(p[0], p[1], p[2], p[3]);
  };
  const glm::vec4 top = at(taps.t00[i]) * (1.0f - fx) + at(taps.t10[i]) * fx;
  const glm::vec4 bottom = at(taps.t01[i]) * (1.0f - fx) + at(taps.t11[i]) * fx;
  return top * (1.0f - fy) + bottom * fy;
}

// The coordinates brought into their wrap's range (a non-finite one reads the first texel), then
// the taps of the level below and, where given (trilinear: some lane may blend it in), above.
template <Wrap WU, Wrap WV>
void taps_in_range(float* cu, float* cv, const std::int32_t* widths, const std::int32_t* heights,
                   LevelTaps& near, LevelTaps* far) {
#pragma omp simd
  for (int i = 0; i < kLanes; ++i) {
    const float a = lane_range<WU>(cu[i]), b = lane_range<WV>(cv[i]);
    cu[i] = std::isfinite(a) ? a : 0.0f;
    cv[i] = std::isfinite(b) ? b : 0.0f;
  }
  level_taps<WU, WV>(cu, cv, widths, heights, near);
  if (far != nullptr) level_taps<WU, WV>(cu, cv, widths, heights, *far);
}

template <Wrap WU>
void taps_for(Wrap wrap_v, float* cu, float* cv, const std::int32_t* widths,
              const std::int32_t* heights, LevelTaps& near, LevelTaps* far) {
  switch (wrap_v) {
    case Wrap::clamp:
      return taps_in_range<WU, Wrap::clamp>(cu, cv, widths, heights, near, far);
    case Wrap::mirror:
      return taps_in_range<WU, Wrap::mirror>(cu, cv, widths, heights, near, far);
    case Wrap::repeat:
      break;
  }
  taps_in_range<WU, Wrap::repeat>(cu, cv, widths, heights, near, far);
}

}  // namespace

bool same_taps(const TextureMap& a, const TextureMap& b) {
  const Texture &ta = *a.texture, &tb = *b.texture;
  // A pyramid's level sizes follow from level 0's (mip_pyramid.h).
  return ta.width() == tb.width() && ta.height() == tb.height() &&
         ta.level_count() == tb.level_count() && a.wrap == b.wrap && a.scale == b.scale &&
         a.rotation == b.rotation && a.offset == b.offset && a.uv_set == b.uv_set;
}

void map_taps(const TextureMap& map, MapFilter filter, const float* u, const float* v,
              const float* log_footprint, std::uint32_t mask, MapTaps& taps) {
  const Texture& texture = *map.texture;
  const int levels = texture.level_count() < kMaxLevels ? texture.level_count() : kMaxLevels;
  alignas(64) std::int32_t widths[kMaxLevels], heights[kMaxLevels];
  for (int l = 0; l < levels; ++l) {
    widths[l] = texture.levels[static_cast<std::size_t>(l)].width;
    heights[l] = texture.levels[static_cast<std::size_t>(l)].height;
  }
  // map_coordinates' and map_level_of_log's per-map constants, in their types and order.
  const float su = map.scale.x, sv = map.scale.y, ou = map.offset.x, ov = map.offset.y;
  const bool turned = map.rotation != 0.0f;
  const float angle = map.rotation * 3.14159265358979323846f / 180.0f;
  const float cr = turned ? std::cos(angle) : 1.0f, sr = turned ? std::sin(angle) : 0.0f;
  const float density = texel_density_log2(texture.width(), texture.height(), su, sv);
  const float top = static_cast<float>(levels - 1);  // all of them: kMaxLevels covers 2^31
  const bool trilinear = filter == MapFilter::trilinear;

  alignas(64) float cu[kLanes], cv[kLanes];
  LevelTaps &near = taps.near, &far = taps.far;
#pragma omp simd
  for (int i = 0; i < kLanes; ++i) {
    const bool on = ((mask >> i) & 1u) != 0;
    const float x = (on ? u[i] : 0.0f) * su, y = (on ? v[i] : 0.0f) * sv;
    cu[i] = turned ? cr * x - sr * y + ou : x + ou;
    cv[i] = turned ? sr * x + cr * y + ov : y + ov;
    // clamp_level, then trilinear's split into a level and the share of the next one.
    const float lod = (on ? log_footprint[i] : 0.0f) + density;
    const float level = trilinear ? (lod > 0.0f ? (lod < top ? lod : top) : 0.0f) : 0.0f;
    const float l0 = std::floor(level);
    const std::int32_t l = static_cast<std::int32_t>(l0);
    taps.far_share[i] = level - l0;
    near.level[i] = l;
    far.level[i] = l + 1 < levels ? l + 1 : l;
  }
  switch (map.wrap[0]) {
    case Wrap::clamp:
      taps_for<Wrap::clamp>(map.wrap[1], cu, cv, widths, heights, near, trilinear ? &far : nullptr);
      break;
    case Wrap::mirror:
      taps_for<Wrap::mirror>(map.wrap[1], cu, cv, widths, heights, near,
                             trilinear ? &far : nullptr);
      break;
    case Wrap::repeat:
      taps_for<Wrap::repeat>(map.wrap[1], cu, cv, widths, heights, near,
                             trilinear ? &far : nullptr);
      break;
  }
}

void read_taps(const Texture& texture, const MapTaps& taps, std::uint32_t mask, MapTexelLanes& out,
               int channels) {
  // Per lane: 16-lane gathers of the same texels (one vector loop, tried when all lanes read
  // the same two levels) took 15 % longer in BM_FirstPass720p on AVX-512 (Skylake-X).
  for (std::uint32_t rest = mask; rest != 0; rest &= rest - 1) {
    const int i = __builtin_ctz(rest);
    glm::vec4 t = blend(texture, taps.near, i);
    const float f = taps.far_share[i];
    if (f > 0.0f) t = t * (1.0f - f) + blend(texture, taps.far, i) * f;
    for (int c = 0; c < channels; ++c) out.texel[c][i] = t[c];
  }
}

}  // namespace gloss

#pragma once
// The bilinear lookup of shading/environment.h (map_bilinear: between texel centres, wrapping in
// u, clamped in t) split in two for kLanes lanes: where to read and with which weights, for all
// lanes in one vector loop (each lane may read an image of its own size: the specular level of
// its material), then the four reads and the blend per lane. The per-lane scalar floor, 64-bit
// index arithmetic and wrap of map_bilinear<float> were, after the map coordinates, the fast
// path's next largest cost. The weights and the blend are the same operations in the same
// order, so the value is map_bilinear's.
#include <cmath>
#include <cstdint>

#include <glm/vec3.hpp>

#include "engine/simd/lanes.h"

namespace gloss {

struct BilinearTaps {
  // Texel indices (row * width + column) of the top-left, top-right, bottom-left and
  // bottom-right texels, and the weights of the right column and of the bottom row.
  alignas(64) std::int32_t i00[kLanes], i10[kLanes], i01[kLanes], i11[kLanes];
  alignas(64) float ax[kLanes], ay[kLanes];
};

// The taps at (u[i], t[i]) in [0, 1] (what map_uv_lanes gives) of a width[i] x height[i] image
// (at most 2^31 texels). The arrays are 64-byte aligned.
inline void bilinear_taps(const float* u, const float* t, const std::int32_t* width,
                          const std::int32_t* height, BilinearTaps& out) {
#pragma omp simd aligned(u, t, width, height : 64)
  for (int i = 0; i < kLanes; ++i) {
    const std::int32_t w = width[i], h = height[i];
    const float x = u[i] * static_cast<float>(w) - 0.5f;
    const float y = t[i] * static_cast<float>(h) - 0.5f;
    const float fx0 = std::floor(x), fy0 = std::floor(y);
    out.ax[i] = x - fx0;
    out.ay[i] = y - fy0;
    // u in [0, 1] puts the left column in [-1, w - 1] and t the top row in [-1, h - 1]; the
    // selects also cover one width either side.
    std::int32_t i0 = static_cast<std::int32_t>(fx0);
    i0 = i0 < 0 ? i0 + w : (i0 >= w ? i0 - w : i0);
    const std::int32_t i1 = i0 + 1 == w ? 0 : i0 + 1;
    const std::int32_t j = static_cast<std::int32_t>(fy0);
    const std::int32_t j0 = j < 0 ? 0 : (j > h - 1 ? h - 1 : j);
    const std::int32_t j1 = j + 1 < 0 ? 0 : (j + 1 > h - 1 ? h - 1 : j + 1);
    out.i00[i] = j0 * w + i0;
    out.i10[i] = j0 * w + i1;
    out.i01[i] = j1 * w + i0;
    out.i11[i] = j1 * w + i1;
  }
}

// Lane i's value from the texels of the image its taps were made for.
inline glm::vec3 bilinear_value(const glm::vec3* texels, const BilinearTaps& taps, int i) {
  const float ax = taps.ax[i], ay = taps.ay[i];
  const glm::vec3 top = texels[taps.i00[i]] * (1.0f - ax) + texels[taps.i10[i]] * ax;
  const glm::vec3 bottom = texels[taps.i01[i]] * (1.0f - ax) + texels[taps.i11[i]] * ax;
  return top * (1.0f - ay) + bottom * ay;
}

}  // namespace gloss

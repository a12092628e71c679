#pragma once
// The UV checker (the editor's `view uv_checker`, like Blender's and Substance's): an image whose
// cells say where on the map a point is, so a model's (u, v) can be read off its surface.
// 8 x 8 cells; cell (i, j) covers u in [i/8, (i+1)/8), v in [j/8, (j+1)/8) (v up, as texture.h):
//   hue        i / 8 of the colour wheel (red at u = 0, yellow, green ... magenta towards u = 1),
//              so a mirrored or turned layout reads as the hues running the other way;
//   brightness 0.2 + 0.8 j / 7 (linear), dark at v = 0, bright at v = 1;
//   checker    cells with i + j odd are pastel (the colour mixed 60 % towards a grey of the same
//              brightness), so neighbouring cells differ and stretching shows in their shapes;
//   grid       the texels on each cell's edge (1 of 64 each side at 512 x 512) dark grey (0.02);
//   marker     a white square over the first 1/32 of u and v: the (0, 0) corner.
// Values are linear (no sRGB decode): what the renderers multiply kd with.
#include <memory>

#include <glm/vec3.hpp>

#include "texture/texture.h"

namespace gloss {

inline constexpr int kUvCheckerCells = 8;
inline constexpr int kUvCheckerSide = 512;  // texels per side: 64 per cell

// The linear colour of texel (x, y) of a side x side checker (row 0 at the top); side a multiple
// of 32 (the marker's 1/32).
glm::vec3 uv_checker_texel(int x, int y, int side);

// The checker's pyramid at side x side, format "made by gloss".
Texture make_uv_checker(int side = kUvCheckerSide);

// One checker at kUvCheckerSide, made on first use and shared (immutable) by every caller.
std::shared_ptr<const Texture> shared_uv_checker();

}  // namespace gloss

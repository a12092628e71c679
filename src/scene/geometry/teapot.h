#pragma once
// Bicubic Bezier patches (the Utah teapot's 32) and their tessellation into a mesh; the patches
// are read by io/model/teapot_reader.h.
#include <array>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/geometry/mesh.h"

namespace gloss {

struct BezierPatches {
  std::vector<std::array<int, 16>> patches;  // 4x4 control-point indices, row-major
  std::vector<glm::vec3> points;             // y-up, converted from the file's z-up
};

// level segments per patch side (1..64): 2 * level^2 triangles per patch. Smooth normals come
// from the cross product of the patch derivatives (with a fallback where they vanish, at the
// lid's and bottom's poles). The teapot rests on y = 0, centred on the y axis, unit scale as in
// the data (about 3.15 tall). Texture coordinates are each patch's parameters and the tangents
// their derivatives (teapot.cpp; docs/scene-format.md, "Texture coordinates").
Mesh tessellate_patches(const BezierPatches& patches, int level, bool smooth = true);

}  // namespace gloss

#pragma once
// Procedural flat meshes: quads (rooms such as the Cornell box) and boxes.
#include <glm/vec3.hpp>

#include "scene/geometry/mesh.h"

namespace gloss {

// Two triangles (a, b, c) and (a, c, d); corners in order around the quad.
Mesh make_quad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d);

// An axis-aligned closed box from lo to hi (12 triangles, outward winding).
Mesh make_box(const glm::vec3& lo, const glm::vec3& hi);

}  // namespace gloss

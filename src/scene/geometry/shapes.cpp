#include "scene/geometry/shapes.h"

#include <glm/common.hpp>

namespace gloss {

Mesh make_quad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d) {
  Mesh mesh;
  mesh.positions = {a, b, c, d};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

// Corner k of the box has x from bit 0, y from bit 1, z from bit 2 (0 = low, 1 = high). Each face
// is listed counter-clockwise seen from outside, so cross(b - a, c - a) points out of the box.
// Corners given in any order are sorted per axis first, so the winding stays outward.
Mesh make_box(const glm::vec3& lo_corner, const glm::vec3& hi_corner) {
  const glm::vec3 lo = glm::min(lo_corner, hi_corner);
  const glm::vec3 hi = glm::max(lo_corner, hi_corner);
  Mesh mesh;
  for (unsigned k = 0; k < 8; ++k) {
    mesh.positions.emplace_back((k & 1u) ? hi.x : lo.x, (k & 2u) ? hi.y : lo.y,
                                (k & 4u) ? hi.z : lo.z);
  }
  static const unsigned faces[6][4] = {
      {0, 4, 6, 2},  // -x
      {1, 3, 7, 5},  // +x
      {0, 1, 5, 4},  // -y
      {2, 6, 7, 3},  // +y
      {0, 2, 3, 1},  // -z
      {4, 5, 7, 6},  // +z
  };
  for (const auto& f : faces) {
    mesh.triangles.emplace_back(f[0], f[1], f[2]);
    mesh.triangles.emplace_back(f[0], f[2], f[3]);
  }
  return mesh;
}

}  // namespace gloss

#include "scene/geometry/shapes.h"

#include <glm/common.hpp>

#include "scene/geometry/tangent_space.h"

namespace gloss {

Mesh make_quad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d) {
  Mesh mesh;
  mesh.positions = {a, b, c, d};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  mesh.uv[0] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
  generate_tangents(mesh);
  return mesh;
}

// Corner k of the box has x from bit 0, y from bit 1, z from bit 2 (0 = low, 1 = high). Each face
// is listed counter-clockwise seen from outside, so cross(b - a, c - a) points out of the box.
// Corners given in any order are sorted per axis first, so the winding stays outward. Each face
// has four vertices of its own, so that it carries the whole image: seen from outside, u runs to
// the right and v up, with "up" +y on the four sides, -z on the top face and +z on the bottom
// (docs/scene-format.md, "Texture coordinates").
Mesh make_box(const glm::vec3& lo_corner, const glm::vec3& hi_corner) {
  const glm::vec3 lo = glm::min(lo_corner, hi_corner);
  const glm::vec3 hi = glm::max(lo_corner, hi_corner);
  auto corner = [&](unsigned k) {
    return glm::vec3((k & 1u) ? hi.x : lo.x, (k & 2u) ? hi.y : lo.y, (k & 4u) ? hi.z : lo.z);
  };
  // Corners of each face in the order (u, v) = (0, 0), (1, 0), (1, 1), (0, 1); the triangles
  // keep the corners and winding of the box's earlier 8-vertex form.
  static const unsigned faces[6][4] = {
      {0, 4, 6, 2},  // -x: u towards +z
      {5, 1, 3, 7},  // +x: u towards -z
      {0, 1, 5, 4},  // -y: u towards +x, v towards +z
      {6, 7, 3, 2},  // +y: u towards +x, v towards -z
      {1, 0, 2, 3},  // -z: u towards -x
      {4, 5, 7, 6},  // +z: u towards +x
  };
  // The triangles of each face as the 8-vertex box listed them, by face-local corner.
  static const unsigned triangles[6][6] = {
      {0, 1, 2, 0, 2, 3}, {1, 2, 3, 1, 3, 0}, {0, 1, 2, 0, 2, 3},
      {3, 0, 1, 3, 1, 2}, {1, 2, 3, 1, 3, 0}, {0, 1, 2, 0, 2, 3},
  };
  static const glm::vec2 uv[4] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
  Mesh mesh;
  for (int f = 0; f < 6; ++f) {
    const auto base = static_cast<unsigned>(mesh.positions.size());
    for (int k = 0; k < 4; ++k) {
      mesh.positions.push_back(corner(faces[f][k]));
      mesh.uv[0].push_back(uv[k]);
    }
    for (int k = 0; k < 6; k += 3) {
      mesh.triangles.emplace_back(base + triangles[f][k], base + triangles[f][k + 1],
                                  base + triangles[f][k + 2]);
    }
  }
  generate_tangents(mesh);
  return mesh;
}

}  // namespace gloss

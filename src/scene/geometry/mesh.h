#pragma once
// An indexed triangle mesh in world space. Smooth meshes carry one unit normal per vertex (the
// spec's interpolated shading normal); flat meshes have none and shade with the geometric normal.
#include <cstddef>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace gloss {

struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;     // empty, or one per position
  std::vector<glm::uvec3> triangles;  // indices into positions (and normals)

  bool smooth() const { return !normals.empty(); }
};

// Removes triangles whose area is zero or not finite (repeated or collinear vertices) and
// returns how many were removed. Loaders call it and warn; degenerate input is never fatal.
std::size_t drop_degenerate_triangles(Mesh& mesh);

// Applies an affine transform to positions and the inverse-transpose to normals (renormalised).
void transform_mesh(Mesh& mesh, const glm::mat4& transform);

// Axis-aligned bounds of the positions; returns false for an empty mesh.
bool mesh_bounds(const Mesh& mesh, glm::vec3& lo, glm::vec3& hi);

}  // namespace gloss

#pragma once
// An indexed triangle mesh in world space. Smooth meshes carry one unit normal per vertex (the
// spec's interpolated shading normal); flat meshes have none and shade with the geometric normal.
// Texture coordinates (up to two sets) and tangents are per vertex too, interpolated with the
// hit's barycentrics (docs/scene-format.md, "Texture coordinates").
#include <cstddef>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace gloss {

struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;     // empty, or one per position
  std::vector<glm::uvec3> triangles;  // indices into positions (and normals)
  // (u, v), v up: empty, or one per position. uv[1] is a second set (a model's); a mesh without
  // it reads set 0 for either.
  std::vector<glm::vec2> uv[2];
  // Tangents of set 0's (u, v): empty, or one per position; xyz the unit tangent (dP/du made
  // perpendicular to the normal), w = +1 or -1 the handedness: the bitangent is
  // w cross(N, T) (MikkTSpace's and glTF's convention).
  std::vector<glm::vec4> tangents;

  bool smooth() const { return !normals.empty(); }
  bool textured() const { return !uv[0].empty(); }
  const std::vector<glm::vec2>& uv_set(int set) const {
    return set == 1 && !uv[1].empty() ? uv[1] : uv[0];
  }
};

// Removes triangles whose area is zero or not finite (repeated or collinear vertices) and
// returns how many were removed. Loaders call it and warn; degenerate input is never fatal.
std::size_t drop_degenerate_triangles(Mesh& mesh);

// Applies an affine transform to positions, the inverse-transpose to normals and the linear part
// to tangents (renormalised; a mirroring transform flips their handedness).
void transform_mesh(Mesh& mesh, const glm::mat4& transform);

// Axis-aligned bounds of the positions; returns false for an empty mesh.
bool mesh_bounds(const Mesh& mesh, glm::vec3& lo, glm::vec3& hi);

}  // namespace gloss

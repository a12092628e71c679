#include "scene/geometry/mesh.h"

#include <cmath>
#include <limits>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace gloss {

namespace {

bool is_finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// A triangle is degenerate when its area is zero or not finite in either precision: in double,
// so exactly collinear or repeated vertices are caught despite float rounding; in float, because
// the renderer computes geometric normals from the float positions and must never normalise a
// zero vector.
bool is_degenerate(const Mesh& mesh, const glm::uvec3& tri) {
  const std::size_t count = mesh.positions.size();
  if (tri.x >= count || tri.y >= count || tri.z >= count) return true;  // cannot be drawn
  if (tri.x == tri.y || tri.y == tri.z || tri.z == tri.x) return true;
  const glm::vec3& a = mesh.positions[tri.x];
  const glm::vec3& b = mesh.positions[tri.y];
  const glm::vec3& c = mesh.positions[tri.z];

  const glm::dvec3 da(a), db(b), dc(c);
  const double area2_d = glm::length(glm::cross(db - da, dc - da));
  if (!(area2_d > 0.0) || !std::isfinite(area2_d)) return true;

  const float area2_f = glm::length(glm::cross(b - a, c - a));
  return !(area2_f > 0.0f) || !std::isfinite(area2_f);
}

}  // namespace

std::size_t drop_degenerate_triangles(Mesh& mesh) {
  std::size_t kept = 0;
  for (const glm::uvec3& tri : mesh.triangles) {
    if (!is_degenerate(mesh, tri)) mesh.triangles[kept++] = tri;
  }
  const std::size_t dropped = mesh.triangles.size() - kept;
  mesh.triangles.resize(kept);
  return dropped;
}

// A mirroring transform (negative determinant) would turn outward winding inward; the triangles
// are rewound so winding and normals keep agreeing. A singular transform flattens the mesh
// (normals have no defined image), so its normals are dropped and it shades flat.
void transform_mesh(Mesh& mesh, const glm::mat4& transform) {
  for (glm::vec3& p : mesh.positions) p = glm::vec3(transform * glm::vec4(p, 1.0f));

  const glm::dmat3 linear = glm::dmat3(glm::dmat4(transform));
  const double det = glm::determinant(linear);
  if (det < 0.0) {
    for (glm::uvec3& tri : mesh.triangles) std::swap(tri.y, tri.z);
  }
  if (det == 0.0 || !std::isfinite(det)) {
    mesh.normals.clear();
    mesh.tangents.clear();
    return;
  }
  for (glm::vec4& t : mesh.tangents) {
    const glm::dvec3 m = linear * glm::dvec3(t.x, t.y, t.z);
    const double len = glm::length(m);
    const glm::vec3 unit = (len > 0.0 && is_finite(m)) ? glm::vec3(m / len) : glm::vec3(1, 0, 0);
    t = glm::vec4(unit, det < 0.0 ? -t.w : t.w);
  }
  if (mesh.normals.empty()) return;
  const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
  for (glm::vec3& n : mesh.normals) {
    const glm::dvec3 m = normal_matrix * glm::dvec3(n);
    const double len = glm::length(m);
    // A zero or non-finite input normal stays unusable; keep it finite rather than NaN.
    n = (len > 0.0 && is_finite(m)) ? glm::vec3(m / len) : glm::vec3(0.0f, 1.0f, 0.0f);
  }
}

bool mesh_bounds(const Mesh& mesh, glm::vec3& lo, glm::vec3& hi) {
  if (mesh.positions.empty()) return false;
  lo = glm::vec3(std::numeric_limits<float>::infinity());
  hi = -lo;
  for (const glm::vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return true;
}

}  // namespace gloss

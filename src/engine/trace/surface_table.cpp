#include "engine/trace/surface_table.h"

#include <algorithm>

#include <glm/geometric.hpp>

namespace gloss {

namespace {
void push(SurfaceTable& t, const glm::vec3& a, const glm::vec3 (&n)[3],
          const glm::vec3& planes = glm::vec3(0.0f)) {
  for (int c = 0; c < 3; ++c) t.a[static_cast<std::size_t>(c)].push_back(a[c]);
  for (int k = 0; k < 3; ++k) {
    for (int c = 0; c < 3; ++c) t.normals[static_cast<std::size_t>(3 * k + c)].push_back(n[k][c]);
    t.planes[static_cast<std::size_t>(k)].push_back(planes[k]);
  }
}
}  // namespace

SurfaceTable make_surface_table(const Scene& scene) {
  SurfaceTable t;
  const glm::vec3 none[3] = {glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
  push(t, glm::vec3(1.0f), none);
  for (const Object& object : scene.objects) {
    t.base.push_back(static_cast<std::uint32_t>(t.a[0].size()));
    t.stride.push_back(1);
    if (object.type == ObjectType::sphere) {
      t.kind.push_back(kSphere);
      push(t, object.center, none);
      continue;
    }
    t.kind.push_back(object.mesh && object.mesh->smooth() ? kSmoothTriangle : kFlatTriangle);
    if (!object.mesh) continue;
    const Mesh& mesh = *object.mesh;
    std::vector<glm::vec3> faces;
    for (const glm::uvec3& tri : mesh.triangles) {
      // In double, rounded once: the flat shading normal is as exact as float can hold.
      const glm::dvec3 p0(mesh.positions[tri.x]), p1(mesh.positions[tri.y]),
          p2(mesh.positions[tri.z]);
      faces.emplace_back(glm::normalize(glm::cross(p1 - p0, p2 - p0)));
    }
    // Exact equality (-0 and +0 components count as equal: the wall keeps its first
    // triangle's signs of zero, which no shading result depends on beyond the sign of a 0).
    const bool one_normal =
        !mesh.smooth() && !faces.empty() &&
        std::all_of(faces.begin(), faces.end(), [&](const glm::vec3& f) { return f == faces[0]; });
    if (one_normal) {
      t.stride.back() = 0;
      push(t, faces[0], none);
      continue;
    }
    for (std::size_t k = 0; k < faces.size(); ++k) {
      const glm::uvec3& tri = mesh.triangles[k];
      if (mesh.smooth()) {
        const glm::vec3 n[3] = {mesh.normals[tri.x], mesh.normals[tri.y], mesh.normals[tri.z]};
        glm::vec3 planes;  // in double, rounded once
        for (int c = 0; c < 3; ++c) {
          const glm::dvec3 corner(mesh.positions[tri[c]]);
          planes[c] = static_cast<float>(glm::dot(corner, glm::dvec3(n[c])));
        }
        push(t, faces[k], n, planes);
      } else {
        push(t, faces[k], none);
      }
    }
  }
  return t;
}

}  // namespace gloss

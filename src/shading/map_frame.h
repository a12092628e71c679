#pragma once
// The MapFrame (hit_textures.h) of a hit on a mesh triangle or a sphere, over a scalar type:
// (u, v) of each set interpolated with the hit's barycentrics (a sphere's from its direction,
// texture/sphere_mapping.h), the footprint of the ray cone (texture/footprint.h), set 0's
// tangent and derivatives. Shared by the reference path and the renderer's lanes.
#include <cstdint>

#include "scene/geometry/mesh.h"
#include "shading/hit_textures.h"
#include "texture/footprint.h"
#include "texture/sphere_mapping.h"

namespace gloss {

// The cone's spread for an image: texture/footprint.h's cone_spread.
// t: hit distance along the unit ray; cos_theta: dot(ray, n_g); b: barycentrics of the corners.
template <class T>
MapFrame<T> mesh_map_frame(const Mesh& mesh, std::uint32_t prim, const T (&b)[3], T t, T spread,
                           T cos_theta) {
  MapFrame<T> f;
  if (!mesh.textured() || prim >= mesh.triangles.size()) return f;
  const glm::uvec3 tri = mesh.triangles[prim];
  const glm::vec<3, T> p0(mesh.positions[tri.x]), p1(mesh.positions[tri.y]),
      p2(mesh.positions[tri.z]);
  // A mesh with one set reads it for set 1 too: the same values, computed once.
  const int sets = mesh.uv[1].empty() ? 1 : 2;
  for (int set = 0; set < sets; ++set) {
    const std::vector<glm::vec2>& uv = mesh.uv_set(set);
    const glm::vec<2, T> t0(uv[tri.x]), t1(uv[tri.y]), t2(uv[tri.z]);
    f.uv[set] = b[0] * t0 + b[1] * t1 + b[2] * t2;
    f.footprint[set] =
        footprint_uv(t, spread, cos_theta, triangle_uv_density(p0, p1, p2, t0, t1, t2));
    if (set == 0) triangle_uv_derivatives(p0, p1, p2, t0, t1, t2, f.dpdu, f.dpdv);
  }
  if (sets == 1) {
    f.uv[1] = f.uv[0];
    f.footprint[1] = f.footprint[0];
  }
  if (mesh.tangents.size() == mesh.positions.size()) {
    const glm::vec4 &a = mesh.tangents[tri.x], &c = mesh.tangents[tri.y], &d = mesh.tangents[tri.z];
    f.tangent = b[0] * glm::vec<3, T>(a) + b[1] * glm::vec<3, T>(c) + b[2] * glm::vec<3, T>(d);
    f.handedness = a.w < 0.0f ? T(-1) : T(1);
  } else if (glm::length(f.dpdu) > T(0)) {
    f.tangent = f.dpdu;
  }
  return f;
}

// A sphere of centre c and radius r hit at p.
template <class T>
MapFrame<T> sphere_map_frame(const glm::vec<3, T>& c, T r, const glm::vec<3, T>& p, T t, T spread,
                             T cos_theta) {
  MapFrame<T> f;
  glm::vec<3, T> d = p - c;
  const T len = glm::length(d);
  d = len > T(0) ? d / len : glm::vec<3, T>(0, 0, 1);
  f.uv[0] = f.uv[1] = sphere_uv(d);
  f.footprint[0] = f.footprint[1] = footprint_uv(t, spread, cos_theta, sphere_uv_density(r, d.y));
  f.tangent = sphere_tangent(d);
  const T cos_beta = std::sqrt(std::max(T(0), T(1) - d.y * d.y));
  constexpr T kPi = T(3.14159265358979323846);
  f.dpdu = T(2) * kPi * r * cos_beta * f.tangent;
  f.dpdv = kPi * r * glm::cross(d, f.tangent);
  return f;
}

}  // namespace gloss

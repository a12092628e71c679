#include "surface.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace gloss {

HitGeometry hit_geometry(const Object& object, std::uint32_t prim, float u, float v) {
  HitGeometry g;
  g.u = u;
  g.v = v;
  g.sphere = object.type == ObjectType::sphere;
  g.smooth = false;
  if (g.sphere) {
    g.p0 = g.p1 = g.p2 = object.center;
    return g;
  }
  const Mesh& mesh = *object.mesh;
  const glm::uvec3 tri = mesh.triangles[prim];
  g.p0 = mesh.positions[tri.x];
  g.p1 = mesh.positions[tri.y];
  g.p2 = mesh.positions[tri.z];
  g.smooth = mesh.smooth();
  if (g.smooth) {
    g.n0 = mesh.normals[tri.x];
    g.n1 = mesh.normals[tri.y];
    g.n2 = mesh.normals[tri.z];
  }
  return g;
}

float refine_sphere_hit(const Object& sphere, const glm::vec3& origin, const glm::dvec3& dir,
                        float t_estimate) {
  const glm::dvec3 o(origin), d(dir), c(sphere.center);
  const glm::dvec3 oc = o - c;
  const double r = sphere.radius;
  const double b = glm::dot(oc, d);
  // |oc|^2 - r^2 as (|oc| - r)(|oc| + r) keeps precision when the eye is far from the sphere.
  const double len = glm::length(oc);
  const double cterm = (len - r) * (len + r);
  const double disc = b * b - cterm;
  if (!(disc >= 0.0)) return t_estimate;  // grazing: Embree's answer stands
  const double root = std::sqrt(disc);
  // The two roots computed without cancellation (q form).
  const double q = b > 0.0 ? -(b + root) : -(b - root);
  double t0 = q, t1 = q != 0.0 ? cterm / q : -b;
  if (t0 > t1) std::swap(t0, t1);
  const double t = std::abs(t0 - t_estimate) <= std::abs(t1 - t_estimate) ? t0 : t1;
  return t > 0.0 ? static_cast<float>(t) : t_estimate;
}

}  // namespace gloss

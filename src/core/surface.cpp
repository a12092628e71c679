#include "surface.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace gloss {

Surface surface_at(const Object& object, std::uint32_t prim, float u, float v,
                   const glm::vec3& origin, const glm::vec3& dir, float t) {
  Surface s;
  s.p = origin + t * dir;
  s.v = -dir;
  if (object.type == ObjectType::sphere) {
    s.n = glm::normalize(s.p - object.center);
    s.ng = s.n;
  } else {
    const Mesh& mesh = *object.mesh;
    const glm::uvec3 tri = mesh.triangles[prim];
    const glm::vec3 p0 = mesh.positions[tri.x], p1 = mesh.positions[tri.y],
                    p2 = mesh.positions[tri.z];
    s.ng = glm::normalize(glm::cross(p1 - p0, p2 - p0));
    s.n = s.ng;
    if (mesh.smooth()) {
      const glm::vec3 interpolated =
          (1.0f - u - v) * mesh.normals[tri.x] + u * mesh.normals[tri.y] + v * mesh.normals[tri.z];
      const float len = glm::length(interpolated);
      // Opposite vertex normals can cancel; the geometric normal is then the only sane choice.
      if (len > 1e-6f) s.n = interpolated / len;
    }
  }
  if (glm::dot(s.ng, s.v) < 0.0f) {  // two-sided surfaces
    s.ng = -s.ng;
    s.n = -s.n;
  }
  return s;
}

float refine_sphere_hit(const Object& sphere, const glm::vec3& origin, const glm::vec3& dir,
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

glm::vec3 shadow_ray_origin(const Surface& s, float t) {
  // p = eye + t dir carries a rounding error of a few ulp of max(|p|, |eye|) and |eye| <= |p| + t;
  // 4e-6 of that is some 30x float epsilon: clear of self-intersection (no acne) yet far below
  // any feature a scene of that size can have. It scales with the scene (1e-3 or 1e4 alike).
  const float magnitude = std::max({std::abs(s.p.x), std::abs(s.p.y), std::abs(s.p.z)}) + t;
  return s.p + s.ng * (4e-6f * std::max(magnitude, 1e-30f));
}

}  // namespace gloss

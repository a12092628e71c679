#include "shading/surface.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace gloss {

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

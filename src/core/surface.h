#pragma once
// The surface quantities of spec/shading.md at a primary hit, rebuilt from the compact hit record
// (object, primitive, t, u, v) that the frame cache keeps per sample.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "scene.h"

namespace gloss {

struct Surface {
  glm::vec3 p;   // hit point, world units
  glm::vec3 n;   // unit shading normal, flipped to the viewer's side
  glm::vec3 ng;  // unit geometric normal, flipped to the viewer's side
  glm::vec3 v;   // unit direction to the eye (= -ray direction)
};

// What a hit needs from its object: the sphere's centre, or the triangle's corners and (smooth
// meshes) vertex normals, with Embree's barycentrics (p = (1 - u - v) p0 + u p1 + v p2).
struct HitGeometry {
  glm::vec3 p0, p1, p2;  // sphere: p0 = centre
  glm::vec3 n0, n1, n2;  // smooth triangles only
  float u, v;
  std::int32_t sphere, smooth;  // 0 or 1
};

HitGeometry hit_geometry(const Object& object, std::uint32_t prim, float u, float v);

// dir must be unit length, in double: the hit point is rebuilt as origin + t dir in double and
// rounded once, since a float direction alone moves the point by 1e-7 of the distance to the eye
// (enough to shift a steep highlight by more than the contract's 1e-4). t is the hit distance
// (refined for spheres, refine_sphere_hit). Only the lane's own kind of normal is computed: the
// packet loops are scalar (GCC does not vectorize them), so selects would only add work.
inline Surface surface_from(const HitGeometry& g, const glm::vec3& origin, const glm::dvec3& dir,
                            float t) {
  Surface s;
  const glm::dvec3 p = glm::dvec3(origin) + static_cast<double>(t) * dir;
  s.p = glm::vec3(p);
  s.v = -glm::vec3(dir);
  if (g.sphere != 0) {
    // From the unrounded point: at shininess 1000 a float normal alone moves the highlight by
    // more than 1e-4.
    s.n = glm::vec3(glm::normalize(p - glm::dvec3(g.p0)));
    s.ng = s.n;
  } else {
    s.ng = glm::normalize(glm::cross(g.p1 - g.p0, g.p2 - g.p0));
    s.n = s.ng;
    if (g.smooth != 0) {
      const glm::vec3 interpolated = (1.0f - g.u - g.v) * g.n0 + g.u * g.n1 + g.v * g.n2;
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

// Recomputes a sphere hit distance in double precision from Embree's float estimate, so that
// hit points and normals stay accurate far from the origin (coordinates up to 1e5).
float refine_sphere_hit(const Object& sphere, const glm::vec3& origin, const glm::dvec3& dir,
                        float t_estimate);

// Where a shadow ray starts: p pushed along ng, never p itself. p = eye + t dir carries a
// rounding error of a few ulp of max(|p|, |eye|), and |eye| <= |p| + t; 4e-6 of that is some 30x
// float epsilon: clear of self-intersection (no acne) yet far below any feature a scene of that
// size can have. It scales with the scene (1e-3 or 1e4 alike).
inline glm::vec3 shadow_ray_origin(const Surface& s, float t) {
  const float magnitude = std::max(std::max(std::abs(s.p.x), std::abs(s.p.y)), std::abs(s.p.z)) + t;
  return s.p + s.ng * (4e-6f * std::max(magnitude, 1e-30f));
}

}  // namespace gloss

#pragma once
// The surface quantities of spec/shading.md at a primary hit, rebuilt from the compact hit record
// (object, primitive, t, u, v) that the frame cache keeps per sample.
#include <cstdint>

#include <glm/vec3.hpp>

#include "scene.h"

namespace gloss {

struct Surface {
  glm::vec3 p;   // hit point, world units
  glm::vec3 n;   // unit shading normal, flipped to the viewer's side
  glm::vec3 ng;  // unit geometric normal, flipped to the viewer's side
  glm::vec3 v;   // unit direction to the eye (= -ray direction)
};

// dir must be unit length. For spheres t is the refined distance (refine_sphere_hit); u, v are
// Embree's barycentrics (p = (1 - u - v) p0 + u p1 + v p2).
Surface surface_at(const Object& object, std::uint32_t prim, float u, float v,
                   const glm::vec3& origin, const glm::vec3& dir, float t);

// Recomputes a sphere hit distance in double precision from Embree's float estimate, so that
// hit points and normals stay accurate far from the origin (coordinates up to 1e5).
float refine_sphere_hit(const Object& sphere, const glm::vec3& origin, const glm::vec3& dir,
                        float t_estimate);

// Where a shadow ray starts: p pushed along ng by a distance that scales with the magnitude of
// the coordinates and the hit distance (the rounding error of p), never p itself.
glm::vec3 shadow_ray_origin(const Surface& s, float t);

}  // namespace gloss

#pragma once
// The surface quantities of docs/spec/shading.md at a primary hit, rebuilt from the compact hit
// record (object, primitive, t, u, v) that the frame cache keeps per sample.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace gloss {

struct Surface {
  glm::vec3 p;   // hit point, world units
  glm::vec3 n;   // unit shading normal, flipped to the viewer's side
  glm::vec3 ng;  // unit geometric normal, flipped to the viewer's side
  glm::vec3 v;   // unit direction to the eye (= -ray direction)
  // World units, >= 0: how far the smooth surface the vertex normals describe lies above the flat
  // triangle at p, along ng (terminator_lift). 0 for spheres, flat triangles and concave sides.
  float lift = 0.0f;
};

// What a hit needs from its primitive (surface_table.h): the sphere's centre or the triangle's
// unit face normal, the vertex normals of smooth triangles and their tangent planes, and
// Embree's barycentrics (n = (1 - u - v) n0 + u n1 + v n2).
struct HitGeometry {
  glm::vec3 a;           // sphere: centre; triangle: unit face normal
  glm::vec3 n0, n1, n2;  // smooth triangles only
  glm::vec3 planes;      // smooth triangles only: dot(P_k, n_k) of corner k's position and normal
  float u, v;
  std::int32_t sphere, smooth;  // 0 or 1
};

// Which kinds of primitive a batch of lanes holds: the packet code instantiates surface_from
// for the kinds present, so a packet of flat walls does no sphere or interpolation maths.
struct LaneKinds {
  bool spheres, smooth;
};

// The shadow terminator (Hanika, "Hacking the Shadow Terminator", Ray Tracing Gems II, ch. 4):
// where vertex normals bend the shading round a coarse mesh, a point the shading normal says
// is lit can lie where the flat triangle faces away from the light, and its shadow ray then
// meets the neighbouring triangles: dark steps along the triangles past the faceted terminator,
// worst under normal maps. Hanika moves p onto the tangent plane of every corner whose plane
// lies above it, p' = p - sum_k b_k min(0, dot(p - P_k, n_k)) n_k, a smooth surface through the
// corners. This returns how far p' lies above the triangle along ng, the flat triangle's normal
// on the viewer's side (side: -1 where the two-sided rule turned it); a shadow ray starts that
// much further along ng where it needs to (shadow_ray_origin). Seen from a concave side every
// corner's plane lies below p: 0. planes[k] = dot(P_k, n_k), so dot(p - P_k, n_k) is
// dot(p, n_k) - planes[k]: float's error there is a few ulp of |p|, far below the offset's own
// 4e-6 |p|. Written with selects (vector code in sample_packet.cpp).
template <class T>
inline T terminator_lift(const glm::tvec3<T>& p, const glm::tvec3<T>& ng, const T (&b)[3],
                         const glm::tvec3<T>& n0, const glm::tvec3<T>& n1, const glm::tvec3<T>& n2,
                         const glm::tvec3<T>& planes, T side) {
  auto raised = [&](const glm::tvec3<T>& n, T plane, T weight) {  // corner k's share
    const T below = std::min(T(0), side * (glm::dot(p, n) - plane));
    return -weight * below * glm::dot(n, ng);  // side n_k . side ng = n_k . ng
  };
  const T lift =
      raised(n0, planes.x, b[0]) + raised(n1, planes.y, b[1]) + raised(n2, planes.z, b[2]);
  return std::max(T(0), lift);
}

// dir must be unit length, in double: the hit point is rebuilt as origin + t dir in double and
// rounded once, since a float direction alone moves the point by 1e-7 of the distance to the eye
// (enough to shift a steep highlight by more than the contract's 1e-4). t is the hit distance
// (refined for spheres, refine_sphere_hit). Written with selects, not branches: the packet code
// (sample_packet.cpp) runs it over 16 lanes at once, so every lane computes each kind of normal
// the batch holds (Spheres, Smooth: whether any lane may be one) and keeps its own.
template <bool Spheres = true, bool Smooth = true>
inline Surface surface_from(const HitGeometry& g, const glm::vec3& origin, const glm::dvec3& dir,
                            float t) {
  auto select = [](bool c, const glm::vec3& a, const glm::vec3& b) {
    return glm::vec3(c ? a.x : b.x, c ? a.y : b.y, c ? a.z : b.z);
  };
  Surface s;
  const glm::dvec3 p = glm::dvec3(origin) + static_cast<double>(t) * dir;
  s.p = glm::vec3(p);
  s.v = -glm::vec3(dir);
  const glm::vec3 n_face = g.a;
  s.ng = n_face;
  s.n = n_face;
  if constexpr (Smooth) {
    const glm::vec3 interpolated = (1.0f - g.u - g.v) * g.n0 + g.u * g.n1 + g.v * g.n2;
    const float len = glm::length(interpolated);
    // Opposite vertex normals can cancel; the geometric normal is then the only sane choice.
    const bool use_smooth = (g.smooth != 0) & (len > 1e-6f);
    const glm::vec3 n_smooth = interpolated * (1.0f / (use_smooth ? len : 1.0f));
    s.n = select(use_smooth, n_smooth, n_face);
    const float b[3] = {1.0f - g.u - g.v, g.u, g.v};
    const float lift = terminator_lift(s.p, n_face, b, g.n0, g.n1, g.n2, g.planes,
                                       glm::dot(n_face, s.v) < 0.0f ? -1.0f : 1.0f);
    s.lift = use_smooth ? lift : 0.0f;
  }
  if constexpr (Spheres) {
    // From the unrounded point; at shininess 1000 a float normal alone moves the highlight by
    // more than 1e-4.
    const glm::vec3 n_sphere(glm::normalize(p - glm::dvec3(g.a)));
    const bool sphere = g.sphere != 0;
    s.ng = select(sphere, n_sphere, s.ng);
    s.n = select(sphere, n_sphere, s.n);
  }
  const float side = glm::dot(s.ng, s.v) < 0.0f ? -1.0f : 1.0f;  // two-sided surfaces
  s.ng *= side;
  s.n *= side;
  return s;
}

// Recomputes a sphere hit distance in double precision from Embree's float estimate, so that
// hit points and normals stay accurate far from the origin (coordinates up to 1e5).
float refine_sphere_hit(const Object& sphere, const glm::vec3& origin, const glm::dvec3& dir,
                        float t_estimate);

// Where a shadow ray towards `towards` (any length; l for a light) starts: p pushed along ng,
// never p itself. p = eye + t dir carries a rounding error of a few ulp of max(|p|, |eye|), and
// |eye| <= |p| + t; 4e-6 of that is some 30x float epsilon: clear of self-intersection (no acne)
// yet far below any feature a scene of that size can have. It scales with the scene (1e-3 or 1e4
// alike). On a smooth triangle the ray leaves from the smooth surface (s.lift further along ng)
// where the triangle faces away from `towards`, and from the triangle where it faces it by
// dot(ng, l) >= kTerminatorCutoff, with a linear blend between: a convex mesh's neighbours lie
// below each triangle's plane, so only rays into that plane need the lift, and the lift kept off
// elsewhere lets no light through a concave crease (a teapot's rim under its lid did, lifted
// always). The 0.1 is ours, chosen by looking at the teapot's rim and terminator; Blender's
// Cycles also limits its terminator offset to lights at grazing angles to the triangle.
inline constexpr float kTerminatorCutoff = 0.1f;

inline float surface_offset(const Surface& s, float t) {
  const float magnitude = std::max(std::max(std::abs(s.p.x), std::abs(s.p.y)), std::abs(s.p.z)) + t;
  return 4e-6f * std::max(magnitude, 1e-30f);
}

inline glm::vec3 shadow_ray_origin(const Surface& s, float t, const glm::vec3& towards) {
  const float reach = kTerminatorCutoff * std::sqrt(glm::dot(towards, towards));
  const float share =
      std::clamp(1.0f - glm::dot(s.ng, towards) / std::max(reach, 1e-30f), 0.0f, 1.0f);
  return s.p + s.ng * (surface_offset(s, t) + s.lift * share);
}

}  // namespace gloss

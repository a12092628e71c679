#pragma once
// A primary hit recomputed in a scalar type T from the primitive Embree found: the exact
// ray-sphere intersection, or Moller-Trumbore against the mesh's triangle, then the normals of
// docs/spec/shading.md (two-sided). Embree answers in float; these make p, n and v as
// accurate as T.
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.h"
#include "shading/surface.h"

namespace gloss {

template <class T>
struct ReferenceHit {
  glm::tvec3<T> p;       // hit point, world units
  glm::tvec3<T> n;       // unit shading normal, flipped to the viewer's side
  glm::tvec3<T> ng;      // unit geometric normal, flipped to the viewer's side
  glm::tvec3<T> v;       // unit direction to the eye
  T t = 0;               // hit distance along the unit direction
  T b[3] = {1, 0, 0};    // barycentric weights of the triangle's corners (meshes)
  T lift = 0;            // the smooth surface's height above the triangle (surface.h)
  bool flipped = false;  // the normals were negated (the viewer sees the back side)
};

// The hit in float, as shadow_ray_origin (surface.h, shared with the fast renderer) takes it.
template <class T>
Surface float_surface(const ReferenceHit<T>& h) {
  Surface s{glm::vec3(h.p), glm::vec3(h.n), glm::vec3(h.ng), glm::vec3(h.v)};
  s.lift = static_cast<float>(h.lift);
  return s;
}

namespace detail {
// Nearest positive root of |o + t d - c| = r for unit d, without cancellation: |oc|^2 - r^2 as
// (|oc| - r)(|oc| + r) and the q form of the quadratic. A grazing ray that Embree hit but T
// misses (negative discriminant by rounding) takes the tangent point. Of two roots ahead, the one
// nearer fallback (Embree's distance); fallback when no root is positive.
template <class T>
T sphere_distance(const glm::tvec3<T>& c, T r, const glm::tvec3<T>& o, const glm::tvec3<T>& d,
                  T fallback) {
  const glm::tvec3<T> oc = o - c;
  const T b = glm::dot(oc, d);
  const T len = glm::length(oc);
  const T cterm = (len - r) * (len + r);
  const T disc = b * b - cterm;
  const T root = disc > T(0) ? std::sqrt(disc) : T(0);
  const T q = b > T(0) ? -(b + root) : -(b - root);
  T t0 = q, t1 = q != T(0) ? cterm / q : -b;
  if (t0 > t1) std::swap(t0, t1);
  // Both ahead: the one Embree reported, which is the far one where a cut-out (an opacity map)
  // took the near one away.
  if (t0 > T(0) && fallback > T(0) && std::abs(t1 - fallback) < std::abs(t0 - fallback)) {
    return t1;
  }
  if (t0 > T(0)) return t0;
  return t1 > T(0) ? t1 : fallback;
}

template <class T>
void finish(ReferenceHit<T>& h) {
  if (glm::dot(h.ng, h.v) < T(0)) {
    h.ng = -h.ng;
    h.n = -h.n;
    h.flipped = true;
  }
}
}  // namespace detail

// o: ray origin, d: unit direction, both in T. t_embree: Embree's distance, used only when T
// finds no positive root.
template <class T>
ReferenceHit<T> sphere_reference_hit(const Object& sphere, const glm::tvec3<T>& o,
                                     const glm::tvec3<T>& d, T t_embree) {
  ReferenceHit<T> h;
  const glm::tvec3<T> c(sphere.center);
  h.t = detail::sphere_distance(c, T(sphere.radius), o, d, t_embree);
  h.p = o + h.t * d;
  h.v = -d;
  const glm::tvec3<T> radial = h.p - c;
  const T len = glm::length(radial);
  h.ng = len > T(0) ? radial / len : h.v;
  h.n = h.ng;
  detail::finish(h);
  return h;
}

// Triangle prim of mesh. (t_embree, u, v): Embree's distance and barycentrics, used when the
// triangle is edge-on to the ray in T (no usable determinant). A triangle of zero area (never
// rendered: the loaders drop them and Embree misses them) gets the normal facing the viewer.
template <class T>
ReferenceHit<T> triangle_reference_hit(const Mesh& mesh, std::uint32_t prim, const glm::tvec3<T>& o,
                                       const glm::tvec3<T>& d, T t_embree, T u, T v) {
  const glm::uvec3 tri = mesh.triangles[prim];
  const glm::tvec3<T> p0(mesh.positions[tri.x]), p1(mesh.positions[tri.y]),
      p2(mesh.positions[tri.z]);
  const glm::tvec3<T> e1 = p1 - p0, e2 = p2 - p0;
  const glm::tvec3<T> pvec = glm::cross(d, e2);
  const T det = glm::dot(e1, pvec);
  T t = t_embree;
  // Relative test: det is |e1| |e2| times a sine; below 1e-12 of that the ray is edge-on.
  if (std::abs(det) > T(1e-12) * glm::length(e1) * glm::length(e2)) {
    const T inv = T(1) / det;
    const glm::tvec3<T> s = o - p0;
    const glm::tvec3<T> qvec = glm::cross(s, e1);
    const T ut = glm::dot(s, pvec) * inv, vt = glm::dot(d, qvec) * inv;
    const T tt = glm::dot(e2, qvec) * inv;
    if (std::isfinite(tt) && tt > T(0)) {
      t = tt;
      u = ut;
      v = vt;
    }
  }
  ReferenceHit<T> h;
  h.t = t;
  h.b[0] = T(1) - u - v;
  h.b[1] = u;
  h.b[2] = v;
  h.p = o + t * d;
  h.v = -d;
  const glm::tvec3<T> cross = glm::cross(e1, e2);
  const T area2 = glm::length(cross);
  h.ng = area2 > T(0) && std::isfinite(area2) ? cross / area2 : h.v;
  h.n = h.ng;
  if (mesh.smooth()) {
    const glm::tvec3<T> interpolated = h.b[0] * glm::tvec3<T>(mesh.normals[tri.x]) +
                                       h.b[1] * glm::tvec3<T>(mesh.normals[tri.y]) +
                                       h.b[2] * glm::tvec3<T>(mesh.normals[tri.z]);
    const T len = glm::length(interpolated);
    // Opposite vertex normals can cancel; the geometric normal is then the only sane choice
    // (the same threshold as surface.h).
    if (len > T(1e-6)) {
      h.n = interpolated / len;
      const glm::tvec3<T> n0(mesh.normals[tri.x]), n1(mesh.normals[tri.y]), n2(mesh.normals[tri.z]);
      const glm::tvec3<T> planes(glm::dot(p0, n0), glm::dot(p1, n1), glm::dot(p2, n2));
      const T side = glm::dot(h.ng, h.v) < T(0) ? T(-1) : T(1);
      h.lift = terminator_lift(h.p, h.ng, h.b, n0, n1, n2, planes, side);
    }
  }
  detail::finish(h);
  return h;
}

}  // namespace gloss

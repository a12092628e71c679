#pragma once
// The contract's texture rules at a hit (docs/spec/shading.md, "Textures") over a scalar type:
// where a hit is in (u, v), what a normal map or a bump map makes of the shading normal, and the
// horizon rule. The renderer's lanes (engine/trace/texture_lanes.cpp) and the reference path call
// these; the raster path's GLSL (shaders/texture_lookup.glsl) is the same arithmetic.
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace gloss {

// A unit vector perpendicular to the unit n (for frames that have no tangent of their own).
template <class T>
glm::vec<3, T> any_perpendicular(const glm::vec<3, T>& n) {
  const glm::vec<3, T> axis =
      std::fabs(n.x) < T(0.9) ? glm::vec<3, T>(1, 0, 0) : glm::vec<3, T>(0, 1, 0);
  return glm::normalize(glm::cross(axis, n));
}

// The tangent t made perpendicular to the unit normal n (Gram-Schmidt), unit length; any
// perpendicular where t has no part across n.
template <class T>
glm::vec<3, T> orthogonal_tangent(const glm::vec<3, T>& n, const glm::vec<3, T>& t) {
  const glm::vec<3, T> p = t - n * glm::dot(n, t);
  const T len = glm::length(p);
  return len > T(1e-12) && std::isfinite(len) ? p / len : any_perpendicular(n);
}

// A normal map's texel as a tangent-space direction: n_t = 2 c - 1 per channel, x and y times
// scale, normalised; (0, 0, 1) where that leaves nothing to normalise.
template <class T>
glm::vec<3, T> tangent_space_normal(const glm::vec<4, T>& texel, T scale) {
  const glm::vec<3, T> n((T(2) * texel.x - T(1)) * scale, (T(2) * texel.y - T(1)) * scale,
                         T(2) * texel.z - T(1));
  const T len = glm::length(n);
  return len > T(0) && std::isfinite(len) ? n / len : glm::vec<3, T>(0, 0, 1);
}

// n = normalize(T n_t.x + B n_t.y + N n_t.z) in the frame of the unit normal N, the tangent t
// (made perpendicular to N) and B = w cross(N, T), w = +1 or -1 the handedness.
template <class T>
glm::vec<3, T> normal_from_map(const glm::vec<3, T>& N, const glm::vec<3, T>& tangent, T w,
                               const glm::vec<3, T>& n_t) {
  const glm::vec<3, T> t = orthogonal_tangent(N, tangent);
  const glm::vec<3, T> b = w * glm::cross(N, t);
  const glm::vec<3, T> n = t * n_t.x + b * n_t.y + N * n_t.z;
  const T len = glm::length(n);
  return len > T(0) && std::isfinite(len) ? n / len : N;
}

// pbrt-v4's BumpMap: the surface displaced along N by height h(u, v) (scene units), its partial
// derivatives dp/du + (h_u - h) / du N and dp/dv + (h_v - h) / dv N from heights one footprint
// step du, dv away, the normal their cross product on N's side. (pbrt's h dN/du term, the
// displacement's own curvature, is left out: it vanishes on flat triangles and is of the order
// of h / radius elsewhere.)
template <class T>
glm::vec<3, T> normal_from_bump(const glm::vec<3, T>& N, const glm::vec<3, T>& dpdu,
                                const glm::vec<3, T>& dpdv, T h, T h_u, T h_v, T du, T dv) {
  const glm::vec<3, T> pu = dpdu - N * glm::dot(N, dpdu) + N * ((h_u - h) / du);
  const glm::vec<3, T> pv = dpdv - N * glm::dot(N, dpdv) + N * ((h_v - h) / dv);
  glm::vec<3, T> n = glm::cross(pu, pv);
  const T len = glm::length(n);
  if (!(len > T(0)) || !std::isfinite(len)) return N;
  n /= len;
  return glm::dot(n, N) < T(0) ? -n : n;
}

// The horizon rule: a mapped normal tilted away from the viewer (dot(n, v) < 0) is mirrored
// about the plane perpendicular to v, back to v's side. n_g and the shadow rays are not touched.
template <class T>
glm::vec<3, T> facing_viewer(const glm::vec<3, T>& n, const glm::vec<3, T>& v) {
  const T d = glm::dot(n, v);
  if (!(d < T(0))) return n;
  return glm::normalize(n - T(2) * d * v);
}

// The footprint step pbrt-v4's BumpMap differentiates over: half the footprint in (u, v), or
// 0.0005 where the footprint is 0.
template <class T>
T bump_step(T footprint_uv) {
  const T du = T(0.5) * footprint_uv;
  return du > T(0) && std::isfinite(du) ? du : T(0.0005);
}

// A triangle's dp/du and dp/dv from its corners' positions and (u, v) (zero where its (u, v)
// area is zero).
template <class T>
void triangle_uv_derivatives(const glm::vec<3, T>& p0, const glm::vec<3, T>& p1,
                             const glm::vec<3, T>& p2, const glm::vec<2, T>& t0,
                             const glm::vec<2, T>& t1, const glm::vec<2, T>& t2,
                             glm::vec<3, T>& dpdu, glm::vec<3, T>& dpdv) {
  const glm::vec<2, T> a = t1 - t0, b = t2 - t0;
  const T det = a.x * b.y - a.y * b.x;
  const glm::vec<3, T> e1 = p1 - p0, e2 = p2 - p0;
  if (!(std::fabs(det) > T(0))) {
    dpdu = dpdv = glm::vec<3, T>(0);
    return;
  }
  dpdu = (b.y * e1 - a.y * e2) / det;
  dpdv = (-b.x * e1 + a.x * e2) / det;
}

}  // namespace gloss

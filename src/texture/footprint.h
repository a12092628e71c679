#pragma once
// The footprint of a sample on a textured surface: one ray-cone formula (Akenine-Moller et al.,
// "Texture Level of Detail Strategies for Real-Time Ray Tracing", Ray Tracing Gems, 2019), used
// by the ray tracer, the reference path and the raster path alike (docs/spec/shading.md,
// "Textures"; the GLSL copy is shaders/texture_lookup.glsl):
//
//   spread    = 2 tan(fov_y / 2) / (H sqrt(N))   a sample's cone angle: a pixel's height at unit
//                                                distance, split among N samples per pixel
//   width     = t spread                          the cone's width at the hit, t the distance
//                                                along the unit ray
//   footprint = width / max(|cos theta|, 1e-6) * rho
//               theta between the ray and the geometric normal; rho = sqrt(A_uv / A_world), the
//               surface's (u, v) area per world area (a triangle's from its corners, a
//               sphere's at the point)
//   level     = log2(footprint * sqrt(|su sv| W H))   for a W x H map scaled by (su, sv);
//               below 0 the map is magnified and level 0 is read
//
// so one footprint in (u, v) units serves every map of the surface.
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace gloss {

// The smallest |cos theta| the footprint divides by: grazing hits read the coarsest levels.
inline constexpr double kMinFootprintCos = 1e-6;

template <class T>
T cone_spread(T fov_y_degrees, int image_height, int spp) {
  const T half = fov_y_degrees * T(0.5) * T(3.14159265358979323846) / T(180);
  return T(2) * std::tan(half) /
         (static_cast<T>(image_height) * std::sqrt(static_cast<T>(spp < 1 ? 1 : spp)));
}

// The footprint in (u, v) units.
template <class T>
T footprint_uv(T t, T spread, T cos_theta, T rho) {
  const T c = std::fabs(cos_theta);
  return t * spread / (c > T(kMinFootprintCos) ? c : T(kMinFootprintCos)) * rho;
}

// log2 of texels per (u, v) unit of a W x H map scaled by (su, sv): 0.5 log2(|su sv| W H).
template <class T>
T texel_density_log2(int width, int height, T scale_u, T scale_v) {
  const T area = std::fabs(scale_u * scale_v) * static_cast<T>(width) * static_cast<T>(height);
  return T(0.5) * std::log2(area);
}

// The mip level of a footprint (any real number; lookups clamp it, texture_lookup.h). A zero
// footprint (degenerate (u, v)) gives -inf: level 0.
template <class T>
T footprint_level(T footprint, T density_log2) {
  return std::log2(footprint) + density_log2;
}

// rho of a triangle: sqrt of its (u, v) area over its world area (0 when either is 0).
template <class T>
T triangle_uv_density(const glm::vec<3, T>& p0, const glm::vec<3, T>& p1, const glm::vec<3, T>& p2,
                      const glm::vec<2, T>& t0, const glm::vec<2, T>& t1,
                      const glm::vec<2, T>& t2) {
  const T world = glm::length(glm::cross(p1 - p0, p2 - p0));
  const glm::vec<2, T> a = t1 - t0, b = t2 - t0;
  const T uv = std::fabs(a.x * b.y - a.y * b.x);
  return world > T(0) && std::isfinite(world) ? std::sqrt(uv / world) : T(0);
}

// rho of a sphere of radius r at latitude beta (sin beta = the unit normal's y), for the
// sphere's (u, v) of surface_uv.h: dA_uv / dA_world = 1 / (2 pi^2 r^2 cos beta).
template <class T>
T sphere_uv_density(T radius, T normal_y) {
  const T c2 = T(1) - normal_y * normal_y;
  const T cos_beta = std::sqrt(c2 > T(1e-12) ? c2 : T(1e-12));
  return T(1) / (radius * std::sqrt(T(2) * cos_beta) * T(3.14159265358979323846));
}

}  // namespace gloss

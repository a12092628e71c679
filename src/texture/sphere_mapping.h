#pragma once
// The (u, v) and tangent of an analytic sphere (docs/scene-format.md, "Texture coordinates"):
// from the unit direction d from the centre to the point,
//   u = 0.5 + atan2(d.x, d.z) / (2 pi)   longitude: 0.5 faces +z (the default camera), u grows
//                                         towards +x, and the seam (u = 0 = 1) is at -z
//   v = 0.5 + asin(d.y) / pi             latitude: 0 at the bottom pole, 1 at the top
// The tangent T = dP/du normalised is (d.z, 0, -d.x) / |...| and the bitangent is cross(N, T)
// (handedness +1), which points up the meridian (dP/dv). At the poles, where dP/du vanishes,
// T = (1, 0, 0): every direction is a meridian there, and this one is continuous with u = 0.75.
#include <cmath>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace gloss {

// The latitude as atan2(d.y, |d.xz|), which equals asin(d.y) for a unit d: GLSL's asin (Mesa's)
// is too coarse for a map's sharp edges, its atan is not (shaders/texture_lookup.glsl).
template <class T>
glm::vec<2, T> sphere_uv(const glm::vec<3, T>& d) {
  constexpr T kPi = T(3.14159265358979323846);
  const T across = std::sqrt(d.x * d.x + d.z * d.z);
  return {T(0.5) + std::atan2(d.x, d.z) / (T(2) * kPi), T(0.5) + std::atan2(d.y, across) / kPi};
}

template <class T>
glm::vec<3, T> sphere_tangent(const glm::vec<3, T>& d) {
  const T len = std::sqrt(d.x * d.x + d.z * d.z);
  if (!(len > T(1e-12))) return {T(1), T(0), T(0)};
  return {d.z / len, T(0), -d.x / len};
}

}  // namespace gloss

#pragma once
// The environment light's map lookup (docs/spec/shading.md, "Environment light"), over a scalar
// type T, for every path: a direction w is turned by -rotation about +y, then
//   phi = atan2(w.x, -w.z), theta = acos(w.y), u = 0.5 + phi / (2 pi), t = theta / pi,
// and L(w) is the map bilinear between texel centres ((i + 0.5) / W, (j + 0.5) / H), wrapping
// around horizontally and clamped at the poles, times the intensity. Also the lobes whose
// integrals the environment's terms are, and their normalisers where they have a closed form.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "base/image.h"
#include "scene/environment.h"
#include "scene/render_settings.h"

namespace gloss {

template <class T>
struct EnvironmentRotation {
  T cos_a = 1, sin_a = 0;  // of the rotation angle
};

template <class T>
EnvironmentRotation<T> environment_rotation(double degrees) {
  const double a = degrees * (3.14159265358979323846 / 180.0);
  return {T(std::cos(a)), T(std::sin(a))};
}

// w turned by -rotation about +y: the direction in the map's own frame.
template <class T>
glm::tvec3<T> to_map_frame(const glm::tvec3<T>& w, const EnvironmentRotation<T>& r) {
  return {w.x * r.cos_a - w.z * r.sin_a, w.y, w.x * r.sin_a + w.z * r.cos_a};
}

// The inverse: a map-frame direction in the world.
template <class T>
glm::tvec3<T> from_map_frame(const glm::tvec3<T>& m, const EnvironmentRotation<T>& r) {
  return {m.x * r.cos_a + m.z * r.sin_a, m.y, -m.x * r.sin_a + m.z * r.cos_a};
}

// (u, t) of a unit map-frame direction: u in [0, 1] left to right, t in [0, 1] top to bottom.
// At the poles (x = z = 0) phi is taken as 0 (u = 0.5): atan2(0, -0) is pi in C and undefined in
// GLSL, and every path must read the same texels there (a floor's normal is the pole).
template <class T>
glm::tvec2<T> map_uv(const glm::tvec3<T>& m) {
  const T pi = T(3.14159265358979323846);
  const T phi = m.x == T(0) && m.z == T(0) ? T(0) : std::atan2(m.x, -m.z);
  const T theta = std::acos(std::clamp(m.y, T(-1), T(1)));
  return {T(0.5) + phi / (T(2) * pi), theta / pi};
}

// The unit map-frame direction of (u, t).
template <class T>
glm::tvec3<T> map_direction(T u, T t) {
  const T pi = T(3.14159265358979323846);
  const T phi = (u - T(0.5)) * T(2) * pi, theta = t * pi;
  const T s = std::sin(theta);
  return {s * std::sin(phi), std::cos(theta), -s * std::cos(phi)};
}

// The map's value at (u, t), bilinear between texel centres, wrapping in u, clamped in t.
template <class T>
glm::tvec3<T> map_bilinear(const Image& map, T u, T t) {
  const T x = u * T(map.width) - T(0.5), y = t * T(map.height) - T(0.5);
  const T fx0 = std::floor(x), fy0 = std::floor(y);
  const T ax = x - fx0, ay = y - fy0;
  const long long w = map.width, h = map.height;
  long long i0 = static_cast<long long>(fx0) % w;
  if (i0 < 0) i0 += w;
  const long long i1 = i0 + 1 == w ? 0 : i0 + 1;
  const long long j0 = std::clamp<long long>(static_cast<long long>(fy0), 0, h - 1);
  const long long j1 = std::clamp<long long>(static_cast<long long>(fy0) + 1, 0, h - 1);
  auto at = [&](long long i, long long j) {
    return glm::tvec3<T>(map.pixels[static_cast<std::size_t>(j * w + i)]);
  };
  const glm::tvec3<T> top = at(i0, j0) * (T(1) - ax) + at(i1, j0) * ax;
  const glm::tvec3<T> bottom = at(i0, j1) * (T(1) - ax) + at(i1, j1) * ax;
  return top * (T(1) - ay) + bottom * ay;
}

// L(w) for unit world direction w: the environment's radiance there, intensity included.
template <class T>
glm::tvec3<T> environment_radiance(const Environment& environment,
                                   const EnvironmentRotation<T>& rotation, const glm::tvec3<T>& w) {
  const glm::tvec2<T> uv = map_uv(to_map_frame(w, rotation));
  return map_bilinear<T>(environment.map->radiance, uv.x, uv.y) * T(environment.intensity);
}

// The specular lobe of the contract at unit w, for a surface with unit normal n, unit v and
// mirror direction r = 2 (n.v) n - v: H(w) max(0, r.w)^alpha (Phong) or
// H(w) max(0, n.normalize(w + v))^alpha (Blinn-Phong, 0 at w = -v), x^0 = 1 for x > 0.
template <class T>
T specular_lobe(ShadingModel model, const glm::tvec3<T>& n, const glm::tvec3<T>& v,
                const glm::tvec3<T>& r, T alpha, const glm::tvec3<T>& w) {
  if (!(glm::dot(n, w) > T(0))) return T(0);
  T c;
  if (model == ShadingModel::phong) {
    c = glm::dot(r, w);
  } else {
    const glm::tvec3<T> h = w + v;
    const T len = glm::length(h);
    if (!(len > T(0))) return T(0);
    c = glm::dot(n, h) / len;
  }
  if (!(c > T(0))) return T(0);
  if (alpha == T(0) || c >= T(1)) return T(1);
  return std::pow(c, alpha);
}

}  // namespace gloss

#pragma once
// A light as the shading contract evaluates it at a point (docs/spec/shading.md, "Light types"):
// its type, world-space position and unit direction, attenuation and cone, resolved once per
// render from the scene's Light and camera (a headlight's direction is given in camera space).
// The renderer (float, factors computed in double), the reference path (double) and the
// inspector all evaluate lights through these functions; shaders/phong_contract.glsl mirrors
// them in GLSL.
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "scene/camera.h"
#include "scene/light.h"
#include "shading/shading.h"

namespace gloss {

template <class T>
struct LightSource {
  using W = WideScalar<T>;
  LightType type = LightType::point;
  glm::tvec3<T> position{0};   // point, spot
  glm::tvec3<T> direction{0};  // directional, spot: unit, the way the light travels, world space
  glm::tvec3<T> attenuation{1, 0, 0};  // point, spot: (c0, c1, c2)
  bool unit_attenuation = false;       // (c0, c1, c2) == (1, 0, 0): att = 1 without arithmetic
  // Spot: the cone in cosines, in the wide type (a cutoff of 0.01 degrees has
  // cos = 1 - 1.5e-8, which float rounds to 1).
  W cos_cutoff = 0, cos_inner = 0;  // cos(cutoff), cos(min(inner, cutoff))
  W exponent = 0;
  bool smooth_edge = false;  // cos(inner) - cos(cutoff) > 1e-6: the edge fades
};

template <class T>
bool operator==(const LightSource<T>& a, const LightSource<T>& b) {
  return a.type == b.type && a.position == b.position && a.direction == b.direction &&
         a.attenuation == b.attenuation && a.unit_attenuation == b.unit_attenuation &&
         a.cos_cutoff == b.cos_cutoff && a.cos_inner == b.cos_inner && a.exponent == b.exponent &&
         a.smooth_edge == b.smooth_edge;
}
template <class T>
bool operator!=(const LightSource<T>& a, const LightSource<T>& b) {
  return !(a == b);
}

// The degrees the contract gives, as a cosine in double.
inline double cos_degrees(double degrees) {
  return std::cos(degrees * (3.14159265358979323846 / 180.0));
}

// The world-space unit direction a light travels (a headlight's camera-space direction turned
// into the camera's frame: x right, y up, -z ahead), in double. direction must not be 0
// (validation refuses it).
inline glm::dvec3 world_light_direction(const Light& light, const Camera& camera) {
  glm::dvec3 d(light.direction);
  if (light.type == LightType::directional && light.follow_camera) {
    const CameraBasis<double> frame = make_camera_basis<double>(camera, 1, 1);
    d = d.x * frame.right + d.y * frame.up - d.z * frame.forward;
  }
  return glm::normalize(d);
}

template <class T>
LightSource<T> make_light_source(const Light& light, const Camera& camera) {
  LightSource<T> s;
  s.type = light.type;
  s.position = glm::tvec3<T>(light.position);
  s.attenuation = glm::tvec3<T>(light.attenuation);
  s.unit_attenuation = light.attenuation == glm::vec3(1.0f, 0.0f, 0.0f);
  if (light.type != LightType::point) {
    s.direction = glm::tvec3<T>(world_light_direction(light, camera));
  }
  const double cutoff = light.cutoff, inner = std::min(light.inner, light.cutoff);
  s.cos_cutoff = cos_degrees(cutoff);
  s.cos_inner = cos_degrees(inner);
  s.exponent = light.exponent;
  s.smooth_edge = s.cos_inner - s.cos_cutoff > 1e-6;
  return s;
}

// The contract's spot factor for cos_t = dot(-l, s): 0 outside the cone, else
// cos_t^exponent (x^0 = 1) times the smooth edge's clamp(...)^2.
template <class W>
W spot_factor(W cos_t, W cos_cutoff, W cos_inner, W exponent, bool smooth_edge) {
  if (!(cos_t >= cos_cutoff)) return W(0);
  W spot = exponent == W(0) ? W(1) : std::pow(std::max(cos_t, W(0)), exponent);
  if (smooth_edge) {
    const W e = std::clamp((cos_t - cos_cutoff) / (cos_inner - cos_cutoff), W(0), W(1));
    spot *= e * e;
  }
  return spot;
}

// The spot factor of source s at point p (1 for point and directional lights), in the wide type:
// l as for a point light, cos_t = dot(-l, s.direction). A spot at p itself (d = 0) gives 0: it
// adds nothing there anyway.
template <class T>
WideScalar<T> spot_at(const glm::tvec3<T>& p, const LightSource<T>& s) {
  using W = WideScalar<T>;
  using V = glm::tvec3<W>;
  if (s.type != LightType::spot) return W(1);
  const V to_light = V(s.position) - V(p);
  const W d = std::sqrt(glm::dot(to_light, to_light));
  if (!(d > W(0))) return W(0);
  const W cos_t = -glm::dot(to_light, V(s.direction)) / d;
  return spot_factor<W>(cos_t, s.cos_cutoff, s.cos_inner, s.exponent, s.smooth_edge);
}

// A spot's factors at p: a point light's geometry with att times `spot` (spot_at). Written
// without branches and always inlined, for the packet code's lane loops.
template <class T>
[[gnu::always_inline]] inline LightFactors<T> spot_light_factors(
    const glm::tvec3<T>& p, const glm::tvec3<T>& n, const glm::tvec3<T>& v, const LightSource<T>& s,
    bool unit_attenuation, WideScalar<T> spot, T vis) {
  using W = WideScalar<T>;
  using V = glm::tvec3<W>;
  const V to_light = V(s.position) - V(p);
  const W d = std::sqrt(glm::dot(to_light, to_light));
  const V l = to_light * (W(1) / d);
  const bool reaches = (d > W(0)) & (d < std::numeric_limits<W>::infinity());
  const W att = unit_attenuation ? W(1) : attenuation(V(s.attenuation), d);
  return factors_along<T>(V(n), V(v), l, reaches, att * spot, vis);
}

// A directional light's factors: l = -D everywhere, att = 1.
template <class T>
[[gnu::always_inline]] inline LightFactors<T> directional_light_factors(const glm::tvec3<T>& n,
                                                                        const glm::tvec3<T>& v,
                                                                        const LightSource<T>& s,
                                                                        T vis) {
  using V = glm::tvec3<WideScalar<T>>;
  return factors_along<T>(V(n), V(v), -V(s.direction), true, WideScalar<T>(1), vis);
}

// shading.h's light_factors for any light type; spot: spot_at(p, s). The point case is
// shading.h's light_factors itself, so point lights keep their bits.
template <class T>
LightFactors<T> source_factors(const glm::tvec3<T>& p, const glm::tvec3<T>& n,
                               const glm::tvec3<T>& v, const LightSource<T>& s, WideScalar<T> spot,
                               T vis) {
  switch (s.type) {
    case LightType::directional:
      return directional_light_factors<T>(n, v, s, vis);
    case LightType::spot:
      return spot_light_factors<T>(p, n, v, s, s.unit_attenuation, spot, vis);
    case LightType::point:
      break;
  }
  return light_factors<T>(p, n, v, s.position, s.attenuation, s.unit_attenuation, vis);
}

}  // namespace gloss

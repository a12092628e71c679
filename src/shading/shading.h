#pragma once
// The shading contract of docs/spec/shading.md as functions over a scalar type T (float for the
// renderer, double for the reference path). Every renderer path calls these; none re-derives them.
#include <cmath>
#include <limits>
#include <type_traits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "scene/render_settings.h"
#include "shading/fast_power.h"

namespace gloss {

// What one point light contributes at one surface sample, before material constants and light
// colours: diffuse = kd * Ld * diffuse_weight, specular = ks * Ls * spec_weight * c^alpha.
// Trivial (no default member initialisers) so caches of them can stay uninitialised until
// filled; write LightFactors<T>{} for zeros.
template <class T>
struct LightFactors {
  T diffuse_weight;  // ndl * att * vis, 0 when ndl <= 0
  T spec_weight;     // att * vis, 0 when ndl <= 0
  T cos_phong;       // R . V = dot(2 ndl n - l, v)
  T cos_blinn;       // N . H = dot(n, normalize(l + v))
};

// att = 1 / (c0 + c1 d + c2 d^2); the loader guarantees c >= 0, not all zero.
template <class T>
T attenuation(const glm::tvec3<T>& c, T d) {
  return T(1) / (c.x + d * (c.y + d * c.z));
}

// The type light_factors computes in: double for float inputs. A float cosine carries about two
// units in the last place (1.2e-7) and c^alpha multiplies that by alpha, so at alpha = 1000 a
// float evaluation misses the contract's 1e-4 against double; computing in double and rounding
// each factor once keeps float within it (tests/reference/test_stability.cpp).
template <class T>
using WideScalar = std::conditional_t<std::is_same_v<T, float>, double, T>;

// The factors of light arriving along unit l (towards the light) with weight att (times the
// spot factor; light_source.h) at a point with unit shading normal n and unit v, in the wide
// type W; reaches: the light is not at the point. Zero factors unless reaches and ndl > 0.
// Written without branches (every quantity computed, then selected): the packet code runs it
// over 16 lanes at once; always inlined, since a call inside a lane loop keeps the loop scalar
// (GCC left it out of light_factors' loop in sample_packet.cpp).
template <class T, class W>
[[gnu::always_inline]] inline LightFactors<T> factors_along(const glm::tvec3<W>& n,
                                                            const glm::tvec3<W>& v,
                                                            const glm::tvec3<W>& l, bool reaches,
                                                            W att, T vis) {
  using V = glm::tvec3<W>;
  const W ndl = glm::dot(n, l);
  const bool lit = reaches & (ndl > W(0));
  const W spec_weight = att * W(vis);
  const W cos_phong = glm::dot(W(2) * ndl * n - l, v);
  const V h = l + v;
  const W h_len = std::sqrt(glm::dot(h, h));
  // l = -v leaves no half vector; ndl > 0 there means n . v < 0, and no highlight is defined.
  const bool has_half = h_len > std::numeric_limits<W>::min() * W(4);
  const W cos_blinn = glm::dot(n, h) / (has_half ? h_len : W(1));
  LightFactors<T> f;
  f.spec_weight = lit ? T(spec_weight) : T(0);
  f.diffuse_weight = lit ? T(ndl * spec_weight) : T(0);
  f.cos_phong = lit ? T(cos_phong) : T(0);
  f.cos_blinn = lit & has_half ? T(cos_blinn) : T(0);
  return f;
}

// Geometry part of the contract for one point light at a surface point. p: point, n: unit
// shading normal, v: unit direction to the eye, both already flipped to the viewer's side
// (two-sided). vis: 1 or 0 from the shadow test. Returns zero factors for d = 0 (a light on the
// surface adds nothing) or ndl <= 0. Other light types: light_source.h, source_factors.
template <class T>
LightFactors<T> light_factors(const glm::tvec3<T>& p_in, const glm::tvec3<T>& n_in,
                              const glm::tvec3<T>& v_in, const glm::tvec3<T>& light_position,
                              const glm::tvec3<T>& attenuation_coeffs, bool unit_attenuation,
                              T vis) {
  using W = WideScalar<T>;
  using V = glm::tvec3<W>;
  const V p(p_in), n(n_in), v(v_in);
  const V to_light = V(light_position) - p;
  const W d = std::sqrt(glm::dot(to_light, to_light));
  const V l = to_light * (W(1) / d);  // one division, not three (vector code: ~10 cycles each)
  const bool reaches = (d > W(0)) & (d < std::numeric_limits<W>::infinity());
  const W att = unit_attenuation ? W(1) : attenuation(V(attenuation_coeffs), d);
  return factors_along<T>(n, v, l, reaches, att, vis);
}

// c^alpha for c > 0, else 0 (alpha = 0 gives 1 wherever c > 0). c is clamped to 1 above (it can
// exceed 1 by rounding only). Results below the normal range flush to 0 in render threads.
template <class T>
T specular_power(T c, T alpha) {
  if (!(c > T(0))) return T(0);
  if (c >= T(1)) return T(1);
  if (alpha == T(0)) return T(1);
  return std::pow(c, alpha);
}

template <class T>
T specular_power(T c, T alpha, PowMode mode) {
  if constexpr (std::is_same_v<T, float>) {
    if (mode == PowMode::fast) return fast_specular_power(c, alpha);
  }
  return specular_power(c, alpha);
}

// The cosine the model raises to alpha.
template <class T>
T model_cosine(const LightFactors<T>& f, ShadingModel model) {
  return model == ShadingModel::phong ? f.cos_phong : f.cos_blinn;
}

// Optional energy normalisation of the specular lobe (off by default).
template <class T>
T energy_normalization(ShadingModel model, T alpha) {
  const T pi = T(3.14159265358979323846);
  return model == ShadingModel::phong ? (alpha + T(2)) / (T(2) * pi) : (alpha + T(8)) / (T(8) * pi);
}

}  // namespace gloss

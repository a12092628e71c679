#pragma once
// The physical reference's BRDF terms (docs/spec/physical-reference.md), in double: the GGX
// (Trowbridge-Reitz) distribution D, Smith's height-correlated masking-shadowing G2 and
// Schlick's Fresnel F. a is the GGX width, roughness^2. Angles enter as cosines (and the half
// vector's sine, which near the peak carries the precision 1 - cos^2 would lose).
#include <algorithm>
#include <cmath>

#include <glm/vec3.hpp>

namespace gloss {

inline constexpr double kPi = 3.14159265358979323846;

// The integral of sin(theta) over [lo, hi], cos(lo) - cos(hi), written as a product of sines so
// that bands a millionth of a radian from the pole keep their digits.
inline double band_measure(double lo, double hi) {
  return 2.0 * std::sin(0.5 * (hi + lo)) * std::sin(0.5 * (hi - lo));
}

// D(h) = a^2 / (pi ((n.h)^2 (a^2 - 1) + 1)^2), written as 1 / (pi a^2 (cos^2 + sin^2 / a^2)^2):
// the same value, without the cancellation of (n.h)^2 (a^2 - 1) + 1 when a^2 is below double's
// epsilon (the mirror limit). cos_h = n.h, sin_h = |n x h| for unit n and h.
inline double ggx_distribution(double cos_h, double sin_h, double a) {
  const double a2 = a * a;
  const double s = cos_h * cos_h + (sin_h * sin_h) / a2;
  return 1.0 / (kPi * a2 * s * s);
}

// The same from n.h alone (sin^2 = 1 - cos^2); for hand checks and plots.
inline double ggx_distribution(double cos_h, double a) {
  const double c = std::clamp(cos_h, 0.0, 1.0);
  return ggx_distribution(c, std::sqrt(std::max(0.0, 1.0 - c * c)), a);
}

// Smith's Lambda for GGX, (sqrt(1 + a^2 tan^2(theta)) - 1) / 2, for cos(theta) in (0, 1],
// written as (sqrt(cos^2 + a^2 sin^2) - cos) / (2 cos) so that it stays exact for cos -> 1 and
// finite for cos -> 0 (where it grows as a / (2 cos)).
inline double smith_lambda(double cos_theta, double a) {
  const double c = std::min(cos_theta, 1.0);
  const double root = std::sqrt(c * c + a * a * std::max(0.0, 1.0 - c * c));
  return (root - c) / (2.0 * c);
}

// Height-correlated masking-shadowing G2 = 1 / (1 + Lambda(l) + Lambda(v)), for n.l, n.v > 0.
inline double smith_g2(double ndl, double ndv, double a) {
  return 1.0 / (1.0 + smith_lambda(ndl, a) + smith_lambda(ndv, a));
}

// Schlick's Fresnel per channel, F = F0 + (1 - F0) (1 - v.h)^5, v.h clamped to [0, 1].
inline glm::dvec3 schlick_fresnel(const glm::dvec3& f0, double vdh) {
  const double m = 1.0 - std::clamp(vdh, 0.0, 1.0);
  const double m2 = m * m;
  return f0 + (glm::dvec3(1.0) - f0) * (m2 * m2 * m);
}

}  // namespace gloss

#include "reference/quadrature_cells.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "shading/environment.h"

namespace gloss::quadrature {

namespace {

constexpr double kPi = 3.14159265358979323846;
// 3-point Gauss-Legendre on [0, 1].
constexpr double kNodes[3] = {0.1127016653792583, 0.5, 0.8872983346207417};
constexpr double kWeights[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};

double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
  return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
}

// cos of the angles between axis and the cone's directions: [lo, hi].
void cosine_range(const glm::dvec3& axis, const glm::dvec3& centre, double radius, double& lo,
                  double& hi) {
  const double a = angle_between(axis, centre);
  lo = std::cos(std::min(kPi, a + radius));
  hi = std::cos(std::max(0.0, a - radius));
}

// a^T M a for M stored as xx, xy, xz, yy, yz, zz.
double quadratic(const double (&m)[6], const glm::dvec3& a) {
  return a.x * a.x * m[0] + 2.0 * a.x * a.y * m[1] + 2.0 * a.x * a.z * m[2] + a.y * a.y * m[3] +
         2.0 * a.y * a.z * m[4] + a.z * a.z * m[5];
}

double power(double c, double alpha) {
  return alpha == 0.0 ? 1.0 : std::pow(std::clamp(c, 0.0, 1.0), alpha);
}

}  // namespace

Moments& Moments::operator+=(const Moments& o) {
  m0 += o.m0;
  for (int c = 0; c < 3; ++c) {
    m1[c] += o.m1[c];
    for (int k = 0; k < 6; ++k) m2[c][k] += o.m2[c][k];
  }
  return *this;
}

Moments Moments::about(const glm::dvec3& c) const {
  Moments out;
  out.m0 = m0;
  const double cc[6] = {c.x * c.x, c.x * c.y, c.x * c.z, c.y * c.y, c.y * c.z, c.z * c.z};
  for (int ch = 0; ch < 3; ++ch) {
    const glm::dvec3& a = m1[ch];
    out.m1[ch] = a - c * m0[ch];
    // m2 - (c a^T + a c^T) + c c^T m0, component by component.
    const double cross[6] = {2 * c.x * a.x, c.x * a.y + c.y * a.x, c.x * a.z + c.z * a.x,
                             2 * c.y * a.y, c.y * a.z + c.z * a.y, 2 * c.z * a.z};
    for (int k = 0; k < 6; ++k) out.m2[ch][k] = m2[ch][k] - cross[k] + cc[k] * m0[ch];
  }
  return out;
}

Moments rectangle_moments(const Image& map, bool unit, double u0, double u1, double t0, double t1,
                          const glm::dvec3& centre) {
  Moments m;
  const double area = (u1 - u0) * (t1 - t0) * 2.0 * kPi * kPi;
  for (int a = 0; a < 3; ++a) {
    const double t = t0 + kNodes[a] * (t1 - t0);
    const double jac = std::sin(kPi * t) * area;
    for (int b = 0; b < 3; ++b) {
      const double u = u0 + kNodes[b] * (u1 - u0);
      const glm::dvec3 l = (unit ? glm::dvec3(1.0) : map_bilinear<double>(map, u, t)) *
                           (kWeights[a] * kWeights[b] * jac);
      const glm::dvec3 w = map_direction<double>(u, t) - centre;
      const double ww[6] = {w.x * w.x, w.x * w.y, w.x * w.z, w.y * w.y, w.y * w.z, w.z * w.z};
      m.m0 += l;
      for (int c = 0; c < 3; ++c) {
        m.m1[c] += l[c] * w;
        for (int k = 0; k < 6; ++k) m.m2[c][k] += l[c] * ww[k];
      }
    }
  }
  return m;
}

Moments unit_moments(double u0, double u1, double t0, double t1) {
  const double a0 = kPi * t0, a1 = kPi * t1;                              // theta
  const double p0 = 2.0 * kPi * (u0 - 0.5), p1 = 2.0 * kPi * (u1 - 0.5);  // phi
  const double c0 = std::cos(a0), c1 = std::cos(a1), s0 = std::sin(a0), s1 = std::sin(a1);
  // Integrals over theta of sin, sin^2, sin^3, sin^2 cos, cos^2 sin, sin cos (all times dtheta).
  const double i_s = c0 - c1;
  const double i_s2 = 0.5 * (a1 - a0) - 0.25 * (std::sin(2.0 * a1) - std::sin(2.0 * a0));
  const double i_s3 = (-c1 + c1 * c1 * c1 / 3.0) - (-c0 + c0 * c0 * c0 / 3.0);
  const double i_s2c = (s1 * s1 * s1 - s0 * s0 * s0) / 3.0;
  const double i_c2s = (c0 * c0 * c0 - c1 * c1 * c1) / 3.0;
  const double i_sc = 0.5 * (s1 * s1 - s0 * s0);
  // Over phi of 1, sin, cos, sin^2, cos^2, sin cos.
  const double j_1 = p1 - p0, j_s = std::cos(p0) - std::cos(p1), j_c = std::sin(p1) - std::sin(p0);
  const double j_s2 = 0.5 * j_1 - 0.25 * (std::sin(2.0 * p1) - std::sin(2.0 * p0));
  const double j_c2 = 0.5 * j_1 + 0.25 * (std::sin(2.0 * p1) - std::sin(2.0 * p0));
  const double j_sc = 0.5 * (std::sin(p1) * std::sin(p1) - std::sin(p0) * std::sin(p0));
  // w = (sin t sin p, cos t, -sin t cos p), dw = sin t dt dp.
  Moments m;
  m.m0 = glm::dvec3(i_s * j_1);
  const glm::dvec3 m1(i_s2 * j_s, i_sc * j_1, -i_s2 * j_c);
  const double m2[6] = {i_s3 * j_s2, i_s2c * j_s,  -i_s3 * j_sc,
                        i_c2s * j_1, -i_s2c * j_c, i_s3 * j_c2};
  for (int c = 0; c < 3; ++c) {
    m.m1[c] = m1;
    for (int k = 0; k < 6; ++k) m.m2[c][k] = m2[k];
  }
  return m;
}

void cone_of(double u0, double u1, double t0, double t1, glm::dvec3& centre, double& radius) {
  centre = map_direction<double>(0.5 * (u0 + u1), 0.5 * (t0 + t1));
  if (u1 - u0 > 0.25) {  // wider than 90 degrees: no useful cone
    radius = kPi;
    return;
  }
  double far = 0.0;
  for (int a = 0; a <= 4; ++a) {
    for (int b = 0; b <= 4; ++b) {
      if (a != 0 && a != 4 && b != 0 && b != 4) continue;  // the boundary only
      far = std::max(far, angle_between(centre, map_direction<double>(u0 + (u1 - u0) * b / 4.0,
                                                                      t0 + (t1 - t0) * a / 4.0)));
    }
  }
  radius = std::min(kPi, 1.01 * far + 1e-12);
}

double Lobe::at(const glm::dvec3& w) const {
  if (!(glm::dot(n, w) > 0.0)) return 0.0;
  double c;
  if (blinn) {
    const glm::dvec3 h = w + v;
    const double len = glm::length(h);
    if (!(len > 0.0)) return 0.0;
    c = glm::dot(n, h) / len;
  } else {
    c = glm::dot(axis, w);
  }
  return c > 0.0 ? power(c, alpha) : 0.0;
}

Lobe::Part Lobe::on(const Moments& m, const glm::dvec3& c, double rho) const {
  Part part;
  double h_lo, h_hi, lo, hi;
  cosine_range(n, c, rho, h_lo, h_hi);
  if (blinn) {
    const double gamma = angle_between(c, v);
    if (gamma + rho >= kPi - 1e-9) {  // -v may lie in the cell: the lobe's own range only
      lo = 0.0;
      hi = 1.0;
    } else {
      // w -> normalize(w + v) stretches chords by at most 1 / |w + v| (angles by pi / 2 more).
      const double rho_h = 1.6 * rho / (2.0 * std::cos(0.5 * (gamma + rho)));
      cosine_range(n, glm::normalize(c + v), rho_h, lo, hi);
    }
  } else {
    cosine_range(axis, c, rho, lo, hi);
  }
  if (!(hi > 0.0) || !(h_hi > 0.0)) {
    part.zero = true;
    return part;
  }
  const double f_max = power(hi, alpha);
  part.smooth = lo > 0.0 && h_lo > 0.0;
  part.bounded = true;
  if (!part.smooth) {  // an edge crosses the cell: the middle of [0, f_max]
    part.value = part.error = 0.5 * f_max * m.m0;
    return part;
  }
  const double f_c = at(c);
  if (blinn) {  // zeroth order, bounded by the lobe's range on the cell
    const double f_min = power(lo, alpha);
    part.value = f_c * m.m0;
    part.error = std::max(f_max - f_c, f_c - f_min) * m.m0;
    return part;
  }
  // Second-order Taylor about c in R^3 (F(x) = (a.x)^alpha, smooth where a.x > 0, which holds
  // on every chord of the cell) with the third-order remainder along the chords.
  const double ac = glm::dot(axis, c);
  const double slope = alpha == 0.0 ? 0.0 : alpha * std::pow(ac, alpha - 1.0);
  const double curve =
      alpha == 0.0 || alpha == 1.0 ? 0.0 : alpha * (alpha - 1.0) * std::pow(ac, alpha - 2.0);
  double third = 0.0;
  if (alpha != 0.0 && alpha != 1.0 && alpha != 2.0) {
    third = std::abs(alpha * (alpha - 1.0) * (alpha - 2.0)) *
            (alpha >= 3.0 ? std::pow(hi, alpha - 3.0) : std::pow(lo, alpha - 3.0));
  }
  for (int ch = 0; ch < 3; ++ch) {  // the moments are about c
    const double first = glm::dot(axis, m.m1[ch]);
    const double second = quadratic(m.m2[ch], axis);
    part.value[ch] = f_c * m.m0[ch] + slope * first + 0.5 * curve * second;
  }
  part.error = (third * rho * rho * rho / 6.0) * m.m0;
  return part;
}

glm::dvec3 sampled_integral(const Image& map, bool unit, const Lobe& lobe, double u0, double u1,
                            double t0, double t1) {
  glm::dvec3 sum(0.0);
  const double area = (u1 - u0) * (t1 - t0) * 2.0 * kPi * kPi;
  for (int a = 0; a < 3; ++a) {
    const double t = t0 + kNodes[a] * (t1 - t0);
    const double jac = std::sin(kPi * t) * area;
    for (int b = 0; b < 3; ++b) {
      const double u = u0 + kNodes[b] * (u1 - u0);
      const double f = lobe.at(map_direction<double>(u, t));
      if (f == 0.0) continue;
      const glm::dvec3 l = unit ? glm::dvec3(1.0) : map_bilinear<double>(map, u, t);
      sum += l * (f * kWeights[a] * kWeights[b] * jac);
    }
  }
  return sum;
}

}  // namespace gloss::quadrature

#include "analysis/lobe/directional_albedo.h"

#include <algorithm>
#include <cmath>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "shading/shading.h"

namespace gloss {

namespace {

constexpr double kPi = 3.14159265358979323846;

using V = glm::dvec3;

}  // namespace

LobeWeights lobe_weights(const AlbedoParams& p, const V& l, const V& v) {
  const V n(0.0, 1.0, 0.0);
  // A point light one unit away with unit attenuation is a light from direction l.
  const LightFactors<double> f =
      light_factors<double>(V(0.0), n, v, l, V(1.0, 0.0, 0.0), true, 1.0);
  LobeWeights c;
  c.diffuse = f.diffuse_weight;
  const double phong_norm =
      p.energy_normalize ? energy_normalization(ShadingModel::phong, p.phong_alpha) : 1.0;
  const double blinn_norm =
      p.energy_normalize ? energy_normalization(ShadingModel::blinn_phong, p.blinn_alpha) : 1.0;
  c.phong = f.spec_weight * specular_power(f.cos_phong, p.phong_alpha) * phong_norm;
  c.blinn = f.spec_weight * specular_power(f.cos_blinn, p.blinn_alpha) * blinn_norm;
  return c;
}

namespace {

// The integral over the sphere of directions of term(v) (n . v)+, directions about axis (b1 in
// the plane of n and axis, b2 = n x ... perpendicular to n) by t = cos(angle to axis) in [-1, 1]
// and azimuth phi. On the ring at t, n . v = A + B cos phi: the visible arc is found exactly, so
// the integrand is smooth where it is integrated (the horizon is an end, not a kink), and by the
// symmetry phi -> -phi half of it is integrated, twice. t in [0, 1] is substituted (below) so
// that a lobe c^k about the axis is flat in the variable integrated. error: the estimated
// absolute error, added to.
template <class Term>
double sphere_integral(const V& axis, const V& b1, const V& b2, double k, double tolerance,
                       const Term& term, double& error) {
  using boost::math::quadrature::gauss_kronrod;
  const V n(0.0, 1.0, 0.0);
  double ring_error = 0.0;  // the largest error of an azimuthal integral
  auto ring = [&](double t) {
    const double s = std::sqrt(std::max(0.0, 1.0 - t * t));
    const double a = t * glm::dot(n, axis), b = s * glm::dot(n, b1);
    double lo = 0.0, hi = kPi;  // the visible arc within [0, pi]
    if (std::abs(b) <= std::abs(a)) {
      if (!(a > 0.0)) return 0.0;  // the whole ring below the horizon
    } else if (b > 0.0) {
      hi = std::acos(std::clamp(-a / b, -1.0, 1.0));
    } else {
      lo = std::acos(std::clamp(-a / b, -1.0, 1.0));
    }
    auto at = [&](double phi) {
      const V v = t * axis + s * (std::cos(phi) * b1 + std::sin(phi) * b2);
      return term(v) * std::max(glm::dot(n, v), 0.0);
    };
    double e = 0.0;
    const double value = 2.0 * gauss_kronrod<double, 15>::integrate(at, lo, hi, 10, tolerance, &e);
    ring_error = std::max(ring_error, 2.0 * e);
    return value;
  };
  // t in [0, 1] as w = 1 - t, substituted by u with w = -ln(1 - u q) / k, q = 1 - e^-k: a lobe
  // c^k ~ e^(-k w) about the axis becomes flat in u, and dw/du stays finite (no endpoint
  // singularity where the integrand is not 0 there). The rings past w = 1 are the lower part's.
  const double q = -std::expm1(-k);
  auto upper = [&](double u) {
    if (k < 1e-6) return ring(1.0 - u);  // no lobe to follow: t itself
    const double w = -std::log1p(-u * q) / k;
    if (!(w < 1.0)) return 0.0;
    return ring(1.0 - w) * q / (k * (1.0 - u * q));
  };
  double upper_error = 0.0, lower_error = 0.0;
  const double top =
      gauss_kronrod<double, 31>::integrate(upper, 0.0, 1.0, 12, tolerance, &upper_error);
  const double bottom =
      gauss_kronrod<double, 31>::integrate(ring, -1.0, 0.0, 12, tolerance, &lower_error);
  // Each ring's error, over the unit measure of u in [0, 1] and of t in [-1, 0].
  error += upper_error + lower_error + 2.0 * ring_error;
  return top + bottom;
}

}  // namespace

AlbedoTerms albedo_terms(const AlbedoParams& params, double incidence_deg) {
  AlbedoTerms out;
  out.incidence_deg = incidence_deg;
  const double ti = std::clamp(incidence_deg, 0.0, 89.999) * kPi / 180.0;
  const V l(-std::sin(ti), std::cos(ti), 0.0);
  const V r(std::sin(ti), std::cos(ti), 0.0);  // the mirror direction
  const V b1(std::cos(ti), -std::sin(ti), 0.0), b2(0.0, 0.0, 1.0);
  const double irradiance = kPi * std::cos(ti);
  double e_diffuse = 0.0, e_phong = 0.0, e_blinn = 0.0;
  // The diffuse weight is the same in every direction: no substitution (k = 0), about n.
  const V n(0.0, 1.0, 0.0), x(1.0, 0.0, 0.0);
  out.diffuse = sphere_integral(
                    n, x, b2, 0.0, params.tolerance,
                    [&](const V& v) { return lobe_weights(params, l, v).diffuse; }, e_diffuse) /
                irradiance;
  // Phong's lobe is c^alpha about R; Blinn-Phong's about R too, about 4 times wider.
  out.phong = sphere_integral(
                  r, b1, b2, params.phong_alpha, params.tolerance,
                  [&](const V& v) { return lobe_weights(params, l, v).phong; }, e_phong) /
              irradiance;
  out.blinn = sphere_integral(
                  r, b1, b2, params.blinn_alpha / 4.0, params.tolerance,
                  [&](const V& v) { return lobe_weights(params, l, v).blinn; }, e_blinn) /
              irradiance;
  out.diffuse_error = e_diffuse / irradiance;
  out.phong_error = e_phong / irradiance;
  out.blinn_error = e_blinn / irradiance;
  return out;
}

glm::dvec3 directional_albedo(const Material& material, const AlbedoTerms& terms,
                              ShadingModel model) {
  const double specular = model == ShadingModel::phong ? terms.phong : terms.blinn;
  return V(material.diffuse) * terms.diffuse + V(material.specular) * specular;
}

std::vector<AlbedoTerms> albedo_curve(const AlbedoParams& params, int count, double max_deg,
                                      const std::atomic<bool>* cancel) {
  std::vector<AlbedoTerms> curve;
  count = std::max(count, 2);
  for (int i = 0; i < count; ++i) {
    if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) return {};
    curve.push_back(albedo_terms(params, max_deg * static_cast<double>(i) / (count - 1)));
  }
  return curve;
}

}  // namespace gloss

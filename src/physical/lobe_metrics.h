#pragma once
// The errors a fit minimises and reports, between two lobes sampled over the same pairs
// (physical/lobe_models.h), each an integral over light and view directions:
//
//   l2:        Ngan, Durand and Matusik 2005 ("Experimental Analysis of BRDF Models", EGSR):
//              sqrt( integral |a - b|^2 d(omega_l) d(omega_v) / integral d(omega_l) d(omega_v) )
//              on the radiance under a unit light (their BRDF times cos(theta_l)); the channels
//              are averaged. Radiance units: a white Lambertian lit head-on sends 1.
//   lightness: the same root mean square on CIE 1976 lightness L* of each linear channel (white
//              1 = L* 100; a cube root above (6/29)^3, linear below), so an error in a dark
//              region counts as the eye sees it, not as its small radiance says. L* units.
//
// Each is the root mean square of a per-pair residual, so a least-squares minimiser
// (physical/least_squares.h) fits either.
#include "physical/lobe_models.h"

namespace gloss {

enum class LobeMetric { l2, lightness };

// "l2" / "lightness"; parse returns false for any other name.
const char* to_string(LobeMetric metric);
bool parse_lobe_metric(const char* name, LobeMetric& metric);

// CIE 1976 L* of a linear value (white 1), and its derivative; negative values count as 0.
double lightness(double x);
double lightness_slope(double x);
// Both at once (one cube root): the fit's residuals and their Jacobian.
void lightness_and_slope(double x, double& value, double& slope);

// The value a metric compares (x itself, or L*(x)).
inline double metric_value(LobeMetric metric, double x) {
  return metric == LobeMetric::l2 ? x : lightness(x);
}

double lobe_error(LobeMetric metric, const LobeSamples& samples, const SampledLobe& a,
                  const SampledLobe& b);

// The residuals of a fit against its target, in both metrics. l2_relative is l2 over the
// target's own root mean square radiance (its l2 against black).
struct LobeResidual {
  double l2 = 0.0;
  double l2_relative = 0.0;
  double lightness = 0.0;
};

LobeResidual lobe_residual(const LobeSamples& samples, const SampledLobe& target,
                           const SampledLobe& candidate);

}  // namespace gloss

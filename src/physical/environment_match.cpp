#include "physical/environment_match.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "physical/brdf_checks.h"
#include "physical/least_squares.h"
#include "physical/lobe_samples.h"
#include "physical/microfacet.h"

namespace gloss {

namespace {

double luminance(const glm::dvec3& c) {
  return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// The model's environment lobe head-on, as a function of the light's angle theta from n: Phong
// (r = n) cos(theta)^alpha, Blinn-Phong (h halfway between w and n) cos(theta / 2)^alpha.
double model_lobe(ShadingModel model, double theta, double alpha) {
  const double c = model == ShadingModel::phong ? std::cos(theta) : std::cos(0.5 * theta);
  return c > 0.0 ? std::pow(c, alpha) : 0.0;
}

}  // namespace

EnvironmentMatch match_environment(const ReferenceBrdf& brdf, ShadingModel model) {
  EnvironmentMatch out;
  const BrdfFunction f = brdf_function(brdf);
  out.albedo_normal = directional_albedo(f, 1.0, brdf.a, 40, 64);
  out.albedo_grazing = directional_albedo(f, std::cos(80.0 * kPi / 180.0), brdf.a, 40, 64);
  // 2 integral of albedo(mu) mu d(mu), midpoints of 16 even cells of mu.
  constexpr int kViews = 16;
  for (int i = 0; i < kViews; ++i) {
    const double mu = (i + 0.5) / kViews;
    out.albedo_mean += directional_albedo(f, mu, brdf.a, 40, 64) * (2.0 * mu / kViews);
  }

  // The reference's reflected lobe head-on over the light's angle theta (the light is 2 theta_h
  // from n), as a density: f(l, n) cos(theta) / albedo, luminance.
  const std::vector<AngleCell> cells = half_angle_cells(2.0 * brdf.a, 20, 16);
  std::vector<double> theta, measure, target;
  const glm::dvec3 n(0.0, 0.0, 1.0);
  const double albedo = luminance(out.albedo_normal);
  for (const AngleCell& c : cells) {
    const glm::dvec3 l(std::sin(c.node), 0.0, std::cos(c.node));
    theta.push_back(c.node);
    measure.push_back(2.0 * kPi * band_measure(c.lo, c.hi));
    target.push_back(albedo > 0.0 ? luminance(f(l, n)) * l.z / albedo : 0.0);
  }
  double target_norm = 0.0;
  for (std::size_t i = 0; i < theta.size(); ++i) target_norm += measure[i] * target[i] * target[i];

  // One parameter, u = log(1 + alpha); the model's lobe divided by its own integral.
  LeastSquaresProblem problem;
  problem.parameters = 1;
  problem.residuals = static_cast<int>(theta.size());
  problem.lower = {0.0};
  problem.upper = {std::log1p(1e6)};
  problem.evaluate = [&](const std::vector<double>& x, std::vector<double>& r,
                         std::vector<double>*) {
    const double alpha = std::expm1(x[0]);
    double integral = 0.0;
    for (std::size_t i = 0; i < theta.size(); ++i) {
      integral += measure[i] * model_lobe(model, theta[i], alpha);
    }
    for (std::size_t i = 0; i < theta.size(); ++i) {
      const double density = model_lobe(model, theta[i], alpha) / integral;
      r[i] = std::sqrt(measure[i]) * (density - target[i]);
    }
  };
  // Start from Walter's Beckmann match, 2 / a^2 - 2 for Blinn-Phong, a quarter of it for Phong.
  const double blinn = std::max(2.0 / (brdf.a * brdf.a) - 2.0, 0.0);
  const double start = model == ShadingModel::phong ? 0.25 * blinn : blinn;
  const LeastSquaresResult fit = least_squares(problem, {std::log1p(std::min(start, 1e6))});
  out.alpha = std::expm1(fit.x[0]);
  out.residual = target_norm > 0.0 ? std::sqrt(fit.cost / target_norm) : 0.0;
  return out;
}

}  // namespace gloss

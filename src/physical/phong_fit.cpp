#include "physical/phong_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "physical/least_squares.h"
#include "physical/microfacet.h"
#include "shading/shading.h"

namespace gloss {

namespace {

constexpr int kScanSteps = 64;

double exponent_of(double u) {
  return std::expm1(u);
}

// What the fit needs of each pair: n.l, the model's cosine, and log(cosine) for c^alpha and its
// derivative.
struct FitPair {
  double weight, ndl, c, log_c;
};

// c^alpha as shading.h's specular_power defines it (0 for c <= 0, 1 for c >= 1 or alpha = 0), as
// exp(alpha log c) from the pair's stored logarithm: the minimiser evaluates it tens of thousands
// of times per step, and exp is about twice as fast as pow. The residuals reported at the end
// are the contract's own (sample_phong, specular_power).
inline double pair_power(const FitPair& p, double alpha) {
  if (!(p.c > 0.0)) return 0.0;
  if (p.c >= 1.0 || alpha == 0.0) return 1.0;
  return std::exp(alpha * p.log_c);
}

std::vector<FitPair> fit_pairs(const LobeSamples& samples, ShadingModel model) {
  std::vector<FitPair> out;
  out.reserve(samples.pairs.size());
  for (const LobePair& p : samples.pairs) {
    const double c = model == ShadingModel::phong ? p.cos_phong : p.cos_blinn;
    out.push_back({p.weight, p.angles.ndl, c, c > 0.0 && c < 1.0 ? std::log(c) : 0.0});
  }
  return out;
}

// For one alpha, per channel, the non-negative kd and ks that minimise the l2 metric: the 2 x 2
// normal equations, or the better of the two one-sided solutions when they give a negative.
// Returns the summed weighted squared error.
double solve_linear(const std::vector<FitPair>& pairs, const SampledLobe& target,
                    const FitOptions& options, double alpha, glm::dvec3& kd, glm::dvec3& ks) {
  const double norm = options.energy_normalize ? energy_normalization(options.model, alpha) : 1.0;
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  glm::dvec3 sxt(0.0), syt(0.0);
  glm::dvec3 tt(0.0);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const FitPair& p = pairs[i];
    const double x = p.ndl, y = norm * pair_power(p, alpha), w = p.weight;
    sxx += w * x * x;
    sxy += w * x * y;
    syy += w * y * y;
    sxt += w * x * target[i];
    syt += w * y * target[i];
    tt += w * target[i] * target[i];
  }
  double error = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double det = sxx * syy - sxy * sxy;
    double a = -1.0, b = -1.0;
    if (det > 1e-300 * std::max(1.0, sxx * syy)) {
      a = (syy * sxt[c] - sxy * syt[c]) / det;
      b = (sxx * syt[c] - sxy * sxt[c]) / det;
    }
    auto err = [&](double ka, double kb) {
      return tt[c] - 2.0 * (ka * sxt[c] + kb * syt[c]) + ka * ka * sxx + 2.0 * ka * kb * sxy +
             kb * kb * syy;
    };
    if (!(a >= 0.0 && b >= 0.0)) {
      const double a_only = sxx > 0.0 ? std::max(0.0, sxt[c] / sxx) : 0.0;
      const double b_only = syy > 0.0 ? std::max(0.0, syt[c] / syy) : 0.0;
      if (err(a_only, 0.0) <= err(0.0, b_only)) {
        a = a_only;
        b = 0.0;
      } else {
        a = 0.0;
        b = b_only;
      }
    }
    kd[c] = a;
    ks[c] = b;
    error += err(a, b);
  }
  return error;
}

// Levenberg-Marquardt over (kd, ks, u = log(1 + alpha)) in the chosen metric, from start.
// Residual (i, c): sqrt(w_i / (3 W)) (g(model_ic) - g(target_ic)), g the metric's value
// (identity or L*), over pairs (and the target sampled on them) whose weights add up to W.
LeastSquaresResult refine(const std::vector<FitPair>& pairs, const SampledLobe& target,
                          const FitOptions& options, const std::vector<double>& start) {
  double total_weight = 0.0;
  for (const FitPair& p : pairs) total_weight += p.weight;
  const double u_max = std::log1p(kMaxFitExponent);
  const double scale = 1.0 / (3.0 * total_weight);
  std::vector<double> root_weight(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i)
    root_weight[i] = std::sqrt(pairs[i].weight * scale);
  std::vector<double> target_value(pairs.size() * 3);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    for (int c = 0; c < 3; ++c)
      target_value[i * 3 + c] = metric_value(options.metric, target[i][c]);
  }
  LeastSquaresProblem problem;
  problem.parameters = 7;
  problem.residuals = static_cast<int>(pairs.size() * 3);
  problem.analytic_jacobian = true;
  problem.lower = {0, 0, 0, 0, 0, 0, 0};
  problem.upper.assign(7, 1e6);
  problem.upper[6] = u_max;
  problem.evaluate = [&](const std::vector<double>& x, std::vector<double>& r,
                         std::vector<double>* jacobian) {
    const double alpha = exponent_of(x[6]);
    const bool normalise = options.energy_normalize;
    const double norm = normalise ? energy_normalization(options.model, alpha) : 1.0;
    // dN/dalpha: 1 / 2pi (Phong) or 1 / 8pi (Blinn-Phong) when on.
    const double dnorm = !normalise                             ? 0.0
                         : options.model == ShadingModel::phong ? 1.0 / (2.0 * kPi)
                                                                : 1.0 / (8.0 * kPi);
    const bool l2 = options.metric == LobeMetric::l2;
    // Rows are independent: any split over threads gives the same bits.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pairs.size(), 2048),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t i = range.begin(); i != range.end(); ++i) {
                          const FitPair& p = pairs[i];
                          const double s = root_weight[i];
                          const double power = pair_power(p, alpha);
                          for (int c = 0; c < 3; ++c) {
                            const double model = x[c] * p.ndl + x[3 + c] * norm * power;
                            const std::size_t row = i * 3 + c;
                            double value = model, slope = s;
                            if (!l2) {
                              lightness_and_slope(model, value, slope);
                              slope *= s;
                            }
                            r[row] = s * (value - target_value[row]);
                            if (jacobian == nullptr) continue;
                            double* j = &(*jacobian)[row * 7];
                            j[c] = slope * p.ndl;
                            j[3 + c] = slope * norm * power;
                            // d/du = d/dalpha (alpha + 1); d(c^alpha)/dalpha = c^alpha ln c
                            j[6] = slope * x[3 + c] * (dnorm * power + norm * power * p.log_c) *
                                   (alpha + 1.0);
                          }
                        }
                      });
  };
  return least_squares(problem, start);
}

}  // namespace

PhongFit fit_phong_lobe(const LobeSamples& samples, const SampledLobe& target,
                        const FitOptions& options) {
  const std::vector<FitPair> pairs = fit_pairs(samples, options.model);
  if (pairs.size() < 64 || target.size() != pairs.size()) {
    throw std::invalid_argument("fit_phong_lobe: " + std::to_string(pairs.size()) +
                                " light-view pairs, too few to fit (widen max_angle_deg)");
  }
  PhongFit fit;
  fit.pairs = static_cast<int>(pairs.size());
  fit.lobe.model = options.model;
  fit.lobe.energy_normalize = options.energy_normalize;

  // 1. The scan: the best alpha with kd and ks solved exactly (l2).
  const double u_max = std::log1p(kMaxFitExponent);
  double best_error = std::numeric_limits<double>::infinity(), best_u = 0.0;
  glm::dvec3 best_kd(0.0), best_ks(0.0);
  for (int k = 0; k <= kScanSteps; ++k) {
    const double u = u_max * k / kScanSteps;
    glm::dvec3 kd, ks;
    const double e = solve_linear(pairs, target, options, exponent_of(u), kd, ks);
    ++fit.evaluations;
    if (e < best_error) {
      best_error = e;
      best_u = u;
      best_kd = kd;
      best_ks = ks;
    }
  }

  // 2. Levenberg-Marquardt from the best of the scan. On lightness, whose optimum lies far from
  // l2's, a first run over every 8th pair gets close at an eighth of the cost.
  std::vector<double> x{best_kd.x, best_kd.y, best_kd.z, best_ks.x, best_ks.y, best_ks.z, best_u};
  if (options.metric == LobeMetric::lightness && pairs.size() > 8 * 64) {
    std::vector<FitPair> coarse;
    SampledLobe coarse_target;
    for (std::size_t i = 0; i < pairs.size(); i += 8) {
      coarse.push_back(pairs[i]);
      coarse_target.push_back(target[i]);
    }
    const LeastSquaresResult first = refine(coarse, coarse_target, options, x);
    fit.evaluations += first.evaluations;
    x = first.x;
  }
  const LeastSquaresResult result = refine(pairs, target, options, x);
  fit.iterations = result.iterations;
  fit.evaluations += result.evaluations;
  fit.lobe.kd = glm::dvec3(result.x[0], result.x[1], result.x[2]);
  fit.lobe.ks = glm::dvec3(result.x[3], result.x[4], result.x[5]);
  fit.lobe.alpha = exponent_of(result.x[6]);
  fit.residual = lobe_residual(samples, target, sample_phong(fit.lobe, samples));
  return fit;
}

PhongFit fit_phong_to_reference(const PhysicalReference& reference, FitOptions options) {
  const ReferenceBrdf brdf = make_reference_brdf(reference);
  options.grid.width = lobe_width_for_ggx(brdf.a);
  const LobeSamples samples = make_lobe_samples(options.grid);
  return fit_phong_lobe(samples, sample_reference(brdf, samples), options);
}

PhongFit fit_phong_to_phong(const PhongLobe& source, FitOptions options) {
  const double blinn_alpha =
      source.model == ShadingModel::phong ? 4.0 * source.alpha : source.alpha;
  options.grid.width = lobe_width_for_exponent(blinn_alpha);
  const LobeSamples samples = make_lobe_samples(options.grid);
  return fit_phong_lobe(samples, sample_phong(source, samples), options);
}

LobeResidual phong_residual(const PhongLobe& lobe, const PhysicalReference& reference,
                            const LobeGrid& grid) {
  const ReferenceBrdf brdf = make_reference_brdf(reference);
  LobeGrid g = grid;
  g.width = lobe_width_for_ggx(brdf.a);
  const LobeSamples samples = make_lobe_samples(g);
  return lobe_residual(samples, sample_reference(brdf, samples), sample_phong(lobe, samples));
}

Material apply_fit(const Material& base, const PhongFit& fit) {
  Material m = base;
  m.diffuse = glm::vec3(fit.lobe.kd);
  m.specular = glm::vec3(fit.lobe.ks);
  m.shininess = static_cast<float>(std::min(fit.lobe.alpha, kMaxFitExponent));
  m.preset.clear();
  return m;
}

}  // namespace gloss

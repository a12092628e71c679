#include "physical/metal_rough_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "physical/least_squares.h"
#include "physical/microfacet.h"

namespace gloss {

namespace {

constexpr int kMetallicSteps = 4;    // metallic 0, 0.25, ..., 1 in the scan
constexpr int kRoughnessSteps = 48;  // roughness even in log over [kMinFitRoughness, 1]

// One pair's radiance as A + base B per channel-independent factors (the header's formula):
//   A = pi n.l spec (0.04 (1 - m) (1 - s) + s),  B = pi n.l (spec m (1 - s) + (1 - m) (1 - F_d) /
//   pi)
// with s = (1 - v.h)^5, spec = D G2 / (4 n.l n.v), F_d = 0.04 + 0.96 s.
struct Affine {
  double a = 0.0, b = 0.0;
};

Affine affine_radiance(const PairCosines& c, double metallic, double roughness) {
  if (!c.valid) return {};
  const double ga = roughness * roughness;
  const double spec =
      ggx_distribution(c.cos_h, c.sin_h, ga) * smith_g2(c.ndl, c.ndv, ga) / (4.0 * c.ndl * c.ndv);
  const double t = 1.0 - std::clamp(c.vdh, 0.0, 1.0);
  const double s = t * t * t * t * t;
  const double fd = 0.04 + 0.96 * s;
  Affine out;
  out.a = kPi * c.ndl * spec * (0.04 * (1.0 - metallic) * (1.0 - s) + s);
  out.b = kPi * c.ndl * (spec * metallic * (1.0 - s) + (1.0 - metallic) * (1.0 - fd) / kPi);
  return out;
}

// For fixed metallic and roughness, the l2-best base colour per channel (a one-unknown least
// squares, clamped to [0, 1], which is the bounded optimum of a convex quadratic in one
// variable). Returns the summed weighted squared error.
double solve_base(const LobeSamples& samples, const SampledLobe& target, double metallic,
                  double roughness, glm::dvec3& base) {
  double sbb = 0.0;
  glm::dvec3 sbr(0.0), srr(0.0), sar(0.0);
  double sab = 0.0, saa = 0.0;
  for (std::size_t i = 0; i < samples.pairs.size(); ++i) {
    const LobePair& p = samples.pairs[i];
    const Affine f = affine_radiance(p.angles, metallic, roughness);
    const double w = p.weight;
    sbb += w * f.b * f.b;
    sab += w * f.a * f.b;
    saa += w * f.a * f.a;
    sbr += w * f.b * target[i];
    sar += w * f.a * target[i];
    srr += w * target[i] * target[i];
  }
  double error = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double x = sbb > 0.0 ? std::clamp((sbr[c] - sab) / sbb, 0.0, 1.0) : 0.0;
    base[c] = x;
    // sum w (a + x b - t)^2
    error += saa + x * x * sbb + srr[c] + 2.0 * x * sab - 2.0 * sar[c] - 2.0 * x * sbr[c];
  }
  return error;
}

}  // namespace

glm::dvec3 metal_rough_radiance(const MetalRough& material, const LobePair& pair) {
  const Affine f = affine_radiance(pair.angles, material.metallic, material.roughness);
  return glm::dvec3(f.a) + material.base_colour * f.b;
}

SampledLobe sample_metal_rough(const MetalRough& material, const LobeSamples& samples) {
  SampledLobe out;
  out.reserve(samples.pairs.size());
  for (const LobePair& pair : samples.pairs) out.push_back(metal_rough_radiance(material, pair));
  return out;
}

LobeGrid grid_for_phong(const PhongLobe& lobe, LobeGrid grid) {
  const double blinn_alpha = lobe.model == ShadingModel::phong ? 4.0 * lobe.alpha : lobe.alpha;
  grid.width = lobe_width_for_exponent(blinn_alpha);
  return grid;
}

namespace {

// Levenberg-Marquardt over (base, metallic, log roughness) in the chosen metric, from x.
// Residual (i, c): sqrt(w_i / (3 W)) (g(model_ic) - g(target_ic)), as the Phong fit's.
LeastSquaresResult refine(const std::vector<LobePair>& pairs, const SampledLobe& target,
                          LobeMetric metric, const std::vector<double>& x) {
  const std::size_t n = pairs.size();
  double total_weight = 0.0;
  for (const LobePair& p : pairs) total_weight += p.weight;
  const double scale = 1.0 / (3.0 * total_weight);
  std::vector<double> root_weight(n), target_value(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    root_weight[i] = std::sqrt(pairs[i].weight * scale);
    for (int c = 0; c < 3; ++c) target_value[3 * i + c] = metric_value(metric, target[i][c]);
  }
  LeastSquaresProblem problem;
  problem.parameters = 5;
  problem.residuals = static_cast<int>(3 * n);
  problem.lower = {0.0, 0.0, 0.0, 0.0, std::log(kMinFitRoughness)};
  problem.upper = {1.0, 1.0, 1.0, 1.0, 0.0};
  problem.evaluate = [&](const std::vector<double>& p, std::vector<double>& r,
                         std::vector<double>*) {
    const double roughness = std::exp(p[4]);
    for (std::size_t i = 0; i < n; ++i) {
      const Affine f = affine_radiance(pairs[i].angles, p[3], roughness);
      for (int c = 0; c < 3; ++c) {
        const double value = metric_value(metric, f.a + p[c] * f.b);
        r[3 * i + c] = root_weight[i] * (value - target_value[3 * i + c]);
      }
    }
  };
  return least_squares(problem, x);
}

}  // namespace

MetalRoughFit fit_metal_rough_lobe(const LobeSamples& samples, const SampledLobe& target,
                                   LobeMetric metric) {
  const std::size_t n = samples.pairs.size();
  if (n < 64 || target.size() != n) {
    throw std::invalid_argument("fit_metal_rough: " + std::to_string(n) +
                                " light-view pairs, too few to fit (widen max_angle_deg)");
  }
  MetalRoughFit fit;
  fit.pairs = static_cast<int>(n);

  // The scan and a first refinement run over every 8th pair (an eighth of the cost, close to
  // the optimum); the last refinement over all of them starts there and takes few steps.
  LobeSamples coarse;
  SampledLobe coarse_target;
  const std::size_t stride = n >= 8 * 64 ? 8 : 1;
  for (std::size_t i = 0; i < n; i += stride) {
    coarse.pairs.push_back(samples.pairs[i]);
    coarse_target.push_back(target[i]);
  }

  // 1. The scan over (metallic, roughness), base colour solved exactly (l2).
  const double u_min = std::log(kMinFitRoughness);
  double best_error = std::numeric_limits<double>::infinity();
  std::vector<double> x(5, 0.0);
  for (int i = 0; i <= kMetallicSteps; ++i) {
    const double m = static_cast<double>(i) / kMetallicSteps;
    for (int j = 0; j <= kRoughnessSteps; ++j) {
      const double u = u_min * (1.0 - static_cast<double>(j) / kRoughnessSteps);
      glm::dvec3 base;
      const double e = solve_base(coarse, coarse_target, m, std::exp(u), base);
      if (e < best_error) {
        best_error = e;
        x = {base.x, base.y, base.z, m, u};
      }
    }
  }

  // 2. Levenberg-Marquardt, coarse then on every pair.
  if (stride > 1) x = refine(coarse.pairs, coarse_target, metric, x).x;
  const LeastSquaresResult result = refine(samples.pairs, target, metric, x);
  fit.iterations = result.iterations;
  fit.material.base_colour = {result.x[0], result.x[1], result.x[2]};
  fit.material.metallic = result.x[3];
  fit.material.roughness = std::exp(result.x[4]);
  fit.residual = lobe_residual(samples, target, sample_metal_rough(fit.material, samples));
  return fit;
}

MetalRoughFit fit_metal_rough(const PhongLobe& source, LobeMetric metric, LobeGrid grid) {
  const LobeSamples samples = make_lobe_samples(grid_for_phong(source, grid));
  return fit_metal_rough_lobe(samples, sample_phong(source, samples), metric);
}

namespace {

LobeGrid grid_for_metal_rough(const MetalRough& material, LobeGrid grid = {}) {
  const double r = std::max(material.roughness, kMinFitRoughness);
  grid.width = lobe_width_for_ggx(r * r);
  return grid;
}

}  // namespace

PhongFit fit_phong_to_metal_rough(const MetalRough& material, const FitOptions& options) {
  LobeGrid coarse = options.grid;
  coarse.per_decade = 10;
  coarse.even = 8;
  coarse.theta_d = 10;
  coarse.phi_d = 10;
  const LobeSamples fit_samples = make_lobe_samples(grid_for_metal_rough(material, coarse));
  PhongFit fit = fit_phong_lobe(fit_samples, sample_metal_rough(material, fit_samples), options);
  const LobeSamples samples = make_lobe_samples(grid_for_metal_rough(material, options.grid));
  fit.residual = lobe_residual(samples, sample_metal_rough(material, samples),
                               sample_phong(fit.lobe, samples));
  fit.pairs = static_cast<int>(samples.pairs.size());
  return fit;
}

LobeResidual residual_to_metal_rough(const PhongLobe& lobe, const MetalRough& material) {
  const LobeSamples samples = make_lobe_samples(grid_for_metal_rough(material));
  return lobe_residual(samples, sample_metal_rough(material, samples), sample_phong(lobe, samples));
}

}  // namespace gloss

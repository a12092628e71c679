#include "physical/threejs_phong_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physical/least_squares.h"
#include "physical/metal_rough_fit.h"
#include "physical/microfacet.h"

namespace gloss {

namespace {

constexpr int kScanSteps = 64;  // shininess even in log(1 + s) over [0, kMaxShininess]
constexpr double kMaxShininess = 1e6;

// Per pair, for a fixed shininess: radiance = x n.l color + (k fres + specular k (1 - fres)),
// k = n.l (s / 2 + 1) / 4 (n.h)^s.
struct Terms {
  double ndl = 0.0, fixed = 0.0, slope = 0.0;
};

Terms terms(const LobePair& pair, double shininess) {
  const PairCosines& c = pair.angles;
  if (!c.valid) return {};
  const double nh = std::clamp(c.cos_h, 0.0, 1.0);
  const double power = shininess == 0.0 ? 1.0 : (nh > 0.0 ? std::pow(nh, shininess) : 0.0);
  const double k = c.ndl * (0.5 * shininess + 1.0) * 0.25 * power;
  const double fres = threejs_fresnel_weight(c.vdh);
  return {c.ndl, k * fres, k * (1.0 - fres)};
}

// The bounded least squares of two unknowns in [0, 1]^2 for one channel: minimises
// sum w (x X + y Y + Z - t)^2 from its moments; the interior optimum if inside, else the best
// of the four edges (each a clamped one-unknown optimum).
struct Moments {
  double xx = 0, xy = 0, yy = 0, xr = 0, yr = 0, rr = 0;  // r = t - Z
};

double quadratic(const Moments& m, double x, double y) {
  return m.rr - 2 * (x * m.xr + y * m.yr) + x * x * m.xx + 2 * x * y * m.xy + y * y * m.yy;
}

void solve_box(const Moments& m, double& x, double& y) {
  const double det = m.xx * m.yy - m.xy * m.xy;
  if (det > 1e-300) {
    x = (m.yy * m.xr - m.xy * m.yr) / det;
    y = (m.xx * m.yr - m.xy * m.xr) / det;
    if (x >= 0 && x <= 1 && y >= 0 && y <= 1) return;
  }
  double best = std::numeric_limits<double>::infinity();
  for (double fixed : {0.0, 1.0}) {
    const double ox = m.xx > 0 ? std::clamp((m.xr - fixed * m.xy) / m.xx, 0.0, 1.0) : 0.0;
    const double oy = m.yy > 0 ? std::clamp((m.yr - fixed * m.xy) / m.yy, 0.0, 1.0) : 0.0;
    if (const double e = quadratic(m, ox, fixed); e < best) best = e, x = ox, y = fixed;
    if (const double e = quadratic(m, fixed, oy); e < best) best = e, x = fixed, y = oy;
  }
}

}  // namespace

double threejs_fresnel_weight(double vdh) {
  const double x = std::clamp(vdh, 0.0, 1.0);
  return std::exp2((-5.55473 * x - 6.98316) * x);
}

glm::dvec3 threejs_phong_radiance(const ThreePhong& material, const LobePair& pair) {
  const Terms t = terms(pair, material.shininess);
  return material.color * t.ndl + glm::dvec3(t.fixed) + material.specular * t.slope;
}

SampledLobe sample_threejs_phong(const ThreePhong& material, const LobeSamples& samples) {
  SampledLobe out;
  out.reserve(samples.pairs.size());
  for (const LobePair& pair : samples.pairs) out.push_back(threejs_phong_radiance(material, pair));
  return out;
}

ThreePhongFit fit_threejs_phong(const PhongLobe& source, LobeMetric metric, LobeGrid grid) {
  const LobeSamples samples = make_lobe_samples(grid_for_phong(source, grid));
  return fit_threejs_phong_lobe(samples, sample_phong(source, samples), metric);
}

ThreePhongFit fit_threejs_phong_lobe(const LobeSamples& samples, const SampledLobe& target,
                                     LobeMetric metric) {
  const std::size_t n = samples.pairs.size();
  ThreePhongFit fit;
  fit.pairs = static_cast<int>(n);

  // 1. Scan the shininess; color and specular solved exactly per channel (l2, in [0, 1]).
  const double u_max = std::log1p(kMaxShininess);
  double best_error = std::numeric_limits<double>::infinity();
  std::vector<double> x(7, 0.0);
  for (int k = 0; k <= kScanSteps; ++k) {
    const double u = u_max * k / kScanSteps, s = std::expm1(u);
    Moments m[3];
    for (std::size_t i = 0; i < n; ++i) {
      const Terms t = terms(samples.pairs[i], s);
      const double w = samples.pairs[i].weight;
      for (int c = 0; c < 3; ++c) {
        const double r = target[i][c] - t.fixed;
        m[c].xx += w * t.ndl * t.ndl;
        m[c].xy += w * t.ndl * t.slope;
        m[c].yy += w * t.slope * t.slope;
        m[c].xr += w * t.ndl * r;
        m[c].yr += w * t.slope * r;
        m[c].rr += w * r * r;
      }
    }
    double error = 0.0;
    std::vector<double> p(7, 0.0);
    p[6] = u;
    for (int c = 0; c < 3; ++c) {
      solve_box(m[c], p[c], p[3 + c]);
      error += quadratic(m[c], p[c], p[3 + c]);
    }
    if (error < best_error) best_error = error, x = p;
  }

  // 2. Levenberg-Marquardt over (color, specular, log(1 + shininess)) in the chosen metric.
  const double scale = 1.0 / (3.0 * samples.total_weight);
  std::vector<double> root_weight(n), target_value(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    root_weight[i] = std::sqrt(samples.pairs[i].weight * scale);
    for (int c = 0; c < 3; ++c) target_value[3 * i + c] = metric_value(metric, target[i][c]);
  }
  LeastSquaresProblem problem;
  problem.parameters = 7;
  problem.residuals = static_cast<int>(3 * n);
  problem.lower.assign(7, 0.0);
  problem.upper = {1.0, 1.0, 1.0, 1.0, 1.0, 1.0, u_max};
  problem.evaluate = [&](const std::vector<double>& p, std::vector<double>& r,
                         std::vector<double>*) {
    const double s = std::expm1(p[6]);
    for (std::size_t i = 0; i < n; ++i) {
      const Terms t = terms(samples.pairs[i], s);
      for (int c = 0; c < 3; ++c) {
        const double value = metric_value(metric, p[c] * t.ndl + t.fixed + p[3 + c] * t.slope);
        r[3 * i + c] = root_weight[i] * (value - target_value[3 * i + c]);
      }
    }
  };
  const LeastSquaresResult result = least_squares(problem, x);
  fit.iterations = result.iterations;
  fit.material.color = {result.x[0], result.x[1], result.x[2]};
  fit.material.specular = {result.x[3], result.x[4], result.x[5]};
  fit.material.shininess = std::expm1(result.x[6]);
  fit.residual = lobe_residual(samples, target, sample_threejs_phong(fit.material, samples));
  return fit;
}

}  // namespace gloss

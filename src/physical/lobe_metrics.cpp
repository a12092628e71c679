#include "physical/lobe_metrics.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace gloss {

namespace {

// CIE 1976: L* = 116 f(Y) - 16, f(t) = t^(1/3) above delta^3, t / (3 delta^2) + 4/29 below.
constexpr double kDelta = 6.0 / 29.0;
constexpr double kDelta3 = kDelta * kDelta * kDelta;

}  // namespace

const char* to_string(LobeMetric metric) {
  return metric == LobeMetric::l2 ? "l2" : "lightness";
}

bool parse_lobe_metric(const char* name, LobeMetric& metric) {
  if (std::strcmp(name, "l2") == 0) {
    metric = LobeMetric::l2;
  } else if (std::strcmp(name, "lightness") == 0) {
    metric = LobeMetric::lightness;
  } else {
    return false;
  }
  return true;
}

double lightness(double x) {
  const double t = x > 0.0 ? x : 0.0;
  const double f = t > kDelta3 ? std::cbrt(t) : t / (3.0 * kDelta * kDelta) + 4.0 / 29.0;
  return 116.0 * f - 16.0;
}

double lightness_slope(double x) {
  if (!(x > 0.0)) return 116.0 / (3.0 * kDelta * kDelta);
  if (x <= kDelta3) return 116.0 / (3.0 * kDelta * kDelta);
  const double c = std::cbrt(x);
  return 116.0 / (3.0 * c * c);
}

void lightness_and_slope(double x, double& value, double& slope) {
  if (!(x > kDelta3)) {
    value = lightness(x);
    slope = 116.0 / (3.0 * kDelta * kDelta);
    return;
  }
  const double c = std::cbrt(x);
  value = 116.0 * c - 16.0;
  slope = 116.0 / (3.0 * c * c);
}

double lobe_error(LobeMetric metric, const LobeSamples& samples, const SampledLobe& a,
                  const SampledLobe& b) {
  if (a.size() != samples.pairs.size() || b.size() != samples.pairs.size()) {
    throw std::invalid_argument("lobe_error: lobes sampled over other pairs");
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    double e = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double d = metric_value(metric, a[i][c]) - metric_value(metric, b[i][c]);
      e += d * d;
    }
    sum += samples.pairs[i].weight * e;
  }
  return std::sqrt(sum / (3.0 * samples.total_weight));
}

LobeResidual lobe_residual(const LobeSamples& samples, const SampledLobe& target,
                           const SampledLobe& candidate) {
  LobeResidual r;
  r.l2 = lobe_error(LobeMetric::l2, samples, target, candidate);
  const double scale = lobe_error(LobeMetric::l2, samples, target, SampledLobe(target.size()));
  r.l2_relative = scale > 0.0 ? r.l2 / scale : 0.0;
  r.lightness = lobe_error(LobeMetric::lightness, samples, target, candidate);
  return r;
}

}  // namespace gloss

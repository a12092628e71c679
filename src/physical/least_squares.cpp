#include "physical/least_squares.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gloss {

namespace {

double sum_of_squares(const std::vector<double>& r) {
  double s = 0.0;
  for (double x : r) s += x * x;
  return s;
}

void project(const LeastSquaresProblem& p, std::vector<double>& x) {
  for (int j = 0; j < p.parameters; ++j) {
    if (!p.lower.empty()) x[j] = std::max(x[j], p.lower[j]);
    if (!p.upper.empty()) x[j] = std::min(x[j], p.upper[j]);
  }
}

// r and the Jacobian at x, by the problem or by forward differences.
void linearise(const LeastSquaresProblem& p, const std::vector<double>& x, std::vector<double>& r,
               std::vector<double>& jacobian, int& evaluations) {
  const int n = p.parameters, m = p.residuals;
  jacobian.assign(static_cast<std::size_t>(m) * n, 0.0);
  if (p.analytic_jacobian) {
    p.evaluate(x, r, &jacobian);
    ++evaluations;
    return;
  }
  p.evaluate(x, r, nullptr);
  ++evaluations;
  std::vector<double> shifted = x, r2(r.size());
  for (int j = 0; j < n; ++j) {
    double h = 1e-7 * std::max(1.0, std::fabs(x[j]));
    // Step inside the bounds.
    if (!p.upper.empty() && x[j] + h > p.upper[j]) h = -h;
    shifted[j] = x[j] + h;
    p.evaluate(shifted, r2, nullptr);
    ++evaluations;
    for (int i = 0; i < m; ++i) jacobian[static_cast<std::size_t>(i) * n + j] = (r2[i] - r[i]) / h;
    shifted[j] = x[j];
  }
}

// Solves the n x n system a y = b in place by Gaussian elimination with partial pivoting;
// false when singular.
bool solve(std::vector<double> a, std::vector<double>& b, int n) {
  for (int k = 0; k < n; ++k) {
    int pivot = k;
    for (int i = k + 1; i < n; ++i) {
      if (std::fabs(a[i * n + k]) > std::fabs(a[pivot * n + k])) pivot = i;
    }
    if (!(std::fabs(a[pivot * n + k]) > 0.0)) return false;
    if (pivot != k) {
      for (int j = 0; j < n; ++j) std::swap(a[k * n + j], a[pivot * n + j]);
      std::swap(b[k], b[pivot]);
    }
    for (int i = k + 1; i < n; ++i) {
      const double f = a[i * n + k] / a[k * n + k];
      for (int j = k; j < n; ++j) a[i * n + j] -= f * a[k * n + j];
      b[i] -= f * b[k];
    }
  }
  for (int k = n - 1; k >= 0; --k) {
    double s = b[k];
    for (int j = k + 1; j < n; ++j) s -= a[k * n + j] * b[j];
    b[k] = s / a[k * n + k];
  }
  return true;
}

}  // namespace

LeastSquaresResult least_squares(const LeastSquaresProblem& p, std::vector<double> start,
                                 const LeastSquaresOptions& options) {
  const int n = p.parameters, m = p.residuals;
  if (n <= 0 || m <= 0 || static_cast<int>(start.size()) != n || !p.evaluate ||
      (!p.lower.empty() && static_cast<int>(p.lower.size()) != n) ||
      (!p.upper.empty() && static_cast<int>(p.upper.size()) != n)) {
    throw std::invalid_argument("least_squares: inconsistent problem");
  }
  LeastSquaresResult result;
  result.x = std::move(start);
  project(p, result.x);
  std::vector<double> r(m), jacobian, trial_r(m);
  linearise(p, result.x, r, jacobian, result.evaluations);
  result.cost = sum_of_squares(r);
  double lambda = 1e-3;
  std::vector<double> jtj(static_cast<std::size_t>(n) * n), g(n);
  while (result.iterations < options.max_iterations) {
    ++result.iterations;
    // Normal equations J^T J and the gradient J^T r.
    std::fill(jtj.begin(), jtj.end(), 0.0);
    std::fill(g.begin(), g.end(), 0.0);
    for (int i = 0; i < m; ++i) {
      const double* row = &jacobian[static_cast<std::size_t>(i) * n];
      for (int a = 0; a < n; ++a) {
        if (row[a] == 0.0) continue;
        g[a] += row[a] * r[i];
        for (int b = a; b < n; ++b) jtj[a * n + b] += row[a] * row[b];
      }
    }
    for (int a = 0; a < n; ++a) {
      for (int b = 0; b < a; ++b) jtj[a * n + b] = jtj[b * n + a];
    }
    // Parameters held at a bound by a gradient pointing out of the box stay there.
    std::vector<bool> active(n, true);
    for (int j = 0; j < n; ++j) {
      const bool at_lower = !p.lower.empty() && result.x[j] <= p.lower[j] && g[j] > 0.0;
      const bool at_upper = !p.upper.empty() && result.x[j] >= p.upper[j] && g[j] < 0.0;
      active[j] = !(at_lower || at_upper);
    }
    bool improved = false, small_step = false;
    while (lambda < 1e16) {
      std::vector<double> a = jtj, step(n);
      for (int j = 0; j < n; ++j) {
        step[j] = active[j] ? -g[j] : 0.0;
        if (!active[j]) {
          for (int k = 0; k < n; ++k) a[j * n + k] = a[k * n + j] = 0.0;
          a[j * n + j] = 1.0;
        } else {
          a[j * n + j] += lambda * std::max(jtj[j * n + j], 1e-300);
        }
      }
      if (!solve(a, step, n)) {
        lambda *= 10.0;
        continue;
      }
      std::vector<double> trial = result.x;
      for (int j = 0; j < n; ++j) trial[j] += step[j];
      project(p, trial);
      p.evaluate(trial, trial_r, nullptr);
      ++result.evaluations;
      const double cost = sum_of_squares(trial_r);
      double moved = 0.0;
      for (int j = 0; j < n; ++j) {
        moved = std::max(moved,
                         std::fabs(trial[j] - result.x[j]) / std::max(1.0, std::fabs(result.x[j])));
      }
      if (std::isfinite(cost) && cost < result.cost) {
        const double gain = (result.cost - cost) / std::max(result.cost, 1e-300);
        result.x = trial;
        result.cost = cost;
        lambda = std::max(lambda / 3.0, 1e-12);
        improved = true;
        small_step = gain < options.relative_tolerance || moved < options.step_tolerance;
        break;
      }
      if (moved < options.step_tolerance) {
        small_step = true;
        break;
      }
      lambda *= 4.0;
    }
    if (!improved || small_step) {
      result.converged = true;
      break;
    }
    linearise(p, result.x, r, jacobian, result.evaluations);
  }
  return result;
}

}  // namespace gloss

#pragma once
// A small bounded least-squares minimiser (Levenberg-Marquardt with Marquardt's diagonal scaling
// and bounds by projection): minimises sum_i r_i(x)^2 over a parameter vector x of a few
// entries. Generic on purpose: the Phong fit (physical/phong_fit.h) is one problem, and the
// reverse fit (the microfacet material closest to a Phong lobe) is another over the same lobes
// and metrics. Deterministic: the same problem and start give the same answer, bit for bit.
#include <functional>
#include <vector>

namespace gloss {

struct LeastSquaresProblem {
  int parameters = 0;
  int residuals = 0;
  // Fills r (residuals entries) for x; when jacobian is not null also fills it row by row
  // (residuals x parameters, d r_i / d x_j at [i * parameters + j]).
  std::function<void(const std::vector<double>& x, std::vector<double>& r,
                     std::vector<double>* jacobian)>
      evaluate;
  bool analytic_jacobian = false;    // false: forward differences of evaluate
  std::vector<double> lower, upper;  // bounds per parameter (empty: unbounded)
};

struct LeastSquaresOptions {
  int max_iterations = 200;
  double relative_tolerance = 1e-10;  // stop when a step lowers the cost by less than this
  double step_tolerance = 1e-12;      // ... or moves x by less than this (relative)
};

struct LeastSquaresResult {
  std::vector<double> x;
  double cost = 0.0;  // sum of squared residuals at x
  int iterations = 0;
  int evaluations = 0;
  bool converged = false;
};

LeastSquaresResult least_squares(const LeastSquaresProblem& problem, std::vector<double> start,
                                 const LeastSquaresOptions& options = {});

}  // namespace gloss

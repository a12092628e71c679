// The generic minimiser (physical/least_squares.h) on problems whose answers are known.
#include <cmath>

#include <gtest/gtest.h>

#include "physical/least_squares.h"

namespace gloss {
namespace {

// Rosenbrock as residuals, r = (10 (y - x^2), 1 - x): minimum 0 at (1, 1), reached from
// (-1.2, 1) along the curved valley; forward-difference Jacobian.
TEST(LeastSquares, RosenbrockFromTheClassicStart) {
  LeastSquaresProblem p;
  p.parameters = 2;
  p.residuals = 2;
  p.evaluate = [](const std::vector<double>& x, std::vector<double>& r, std::vector<double>*) {
    r[0] = 10.0 * (x[1] - x[0] * x[0]);
    r[1] = 1.0 - x[0];
  };
  const LeastSquaresResult result = least_squares(p, {-1.2, 1.0});
  EXPECT_TRUE(result.converged);
  EXPECT_NEAR(result.x[0], 1.0, 1e-6);
  EXPECT_NEAR(result.x[1], 1.0, 1e-6);
  EXPECT_LT(result.cost, 1e-12);
}

// A straight line through (0, 1), (1, 3), (2, 5) plus symmetric noise +-0.1 on the middle
// point's neighbours: y = 1 + 2 x exactly (the noise cancels), with an analytic Jacobian.
TEST(LeastSquares, LinearFitIsExact) {
  const double xs[] = {0, 1, 2, 3}, ys[] = {1.1, 3.0, 5.0, 6.9};
  // Normal equations by hand: sum x = 6, sum x^2 = 14, sum y = 16, sum xy = 0 + 3 + 10 + 20.7
  // = 33.7; slope = (4 33.7 - 6 16) / (4 14 - 36) = 38.8 / 20 = 1.94;
  // intercept = (16 - 1.94 6) / 4 = 1.09.
  LeastSquaresProblem p;
  p.parameters = 2;
  p.residuals = 4;
  p.analytic_jacobian = true;
  p.evaluate = [&](const std::vector<double>& x, std::vector<double>& r, std::vector<double>* j) {
    for (int i = 0; i < 4; ++i) {
      r[i] = x[0] + x[1] * xs[i] - ys[i];
      if (j != nullptr) {
        (*j)[i * 2] = 1.0;
        (*j)[i * 2 + 1] = xs[i];
      }
    }
  };
  const LeastSquaresResult result = least_squares(p, {0.0, 0.0});
  EXPECT_NEAR(result.x[0], 1.09, 1e-9);
  EXPECT_NEAR(result.x[1], 1.94, 1e-9);
}

// A bound that binds: minimise (x + 1)^2 + (y - 2)^2 with x >= 0 and y <= 1: (0, 1).
TEST(LeastSquares, BoundsHold) {
  LeastSquaresProblem p;
  p.parameters = 2;
  p.residuals = 2;
  p.lower = {0.0, -10.0};
  p.upper = {10.0, 1.0};
  p.evaluate = [](const std::vector<double>& x, std::vector<double>& r, std::vector<double>*) {
    r[0] = x[0] + 1.0;
    r[1] = x[1] - 2.0;
  };
  const LeastSquaresResult result = least_squares(p, {5.0, -5.0});
  EXPECT_EQ(result.x[0], 0.0);
  EXPECT_EQ(result.x[1], 1.0);
  EXPECT_NEAR(result.cost, 2.0, 1e-12);
}

// Same problem, same start: the same bits.
TEST(LeastSquares, Deterministic) {
  LeastSquaresProblem p;
  p.parameters = 3;
  p.residuals = 5;
  p.evaluate = [](const std::vector<double>& x, std::vector<double>& r, std::vector<double>*) {
    for (int i = 0; i < 5; ++i)
      r[i] = x[0] * std::exp(-x[1] * i) + x[2] - (2.0 * std::exp(-0.5 * i) + 0.3);
  };
  const LeastSquaresResult a = least_squares(p, {1.0, 1.0, 0.0});
  const LeastSquaresResult b = least_squares(p, {1.0, 1.0, 0.0});
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.cost, b.cost);
  EXPECT_NEAR(a.x[0], 2.0, 1e-5);
  EXPECT_NEAR(a.x[1], 0.5, 1e-5);
  EXPECT_NEAR(a.x[2], 0.3, 1e-5);
}

// An inconsistent problem is refused.
TEST(LeastSquares, RefusesInconsistentProblems) {
  LeastSquaresProblem p;
  p.parameters = 2;
  p.residuals = 1;
  p.evaluate = [](const std::vector<double>&, std::vector<double>& r, std::vector<double>*) {
    r[0] = 0.0;
  };
  EXPECT_THROW(least_squares(p, {1.0}), std::invalid_argument);
  p.lower = {0.0};
  EXPECT_THROW(least_squares(p, {1.0, 2.0}), std::invalid_argument);
}

}  // namespace
}  // namespace gloss

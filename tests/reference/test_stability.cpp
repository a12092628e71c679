// Numerical stability of the shading contract at the edges of the parameter space
// (docs/spec/shading.md, "Numerical expectations"): the shading functions of shading.h in float and
// double, and whole renders (fast float renderer and reference path) of degenerate geometry and
// scaled scenes.
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "engine/renderer.h"
#include "reference/reference_renderer.h"
#include "shading/shading.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

// The shininess values of the issue, in increasing order.
const double kShininess[] = {0, 1e-8, 1e-4, 1, 128, 1e3, 1e6};

template <class T>
using V3 = glm::tvec3<T>;

// Diffuse and specular of one light with kd = ks = Ld = Ls = 1 (so both are bounded by att),
// composed from shading.h exactly as the renderers compose them.
template <class T>
struct Terms {
  T diffuse, specular;
};

template <class T>
Terms<T> terms(const V3<T>& p, const V3<T>& n, const V3<T>& v, const V3<T>& light, const V3<T>& att,
               T alpha, ShadingModel model, PowMode pow) {
  const LightFactors<T> f = light_factors<T>(p, n, v, light, att, false, T(1));
  return {f.diffuse_weight, f.spec_weight * specular_power<T>(model_cosine(f, model), alpha, pow)};
}

// A unit vector at angle acos(c) from +z in the x-z plane (x = sqrt(1 - c^2) in long double).
template <class T>
V3<T> at_cosine(long double c, long double sign_x = 1) {
  return V3<T>(T(sign_x * std::sqrt(1.0L - c * c)), T(0), T(c));
}

struct Case {
  const char* name;
  V3<double> p, n, v, light, att;
};

// Surface geometry at the extremes; n is +z unless said otherwise.
std::vector<Case> extreme_cases() {
  const V3<double> z(0, 0, 1), one(1, 0, 0), far_p(1e5, -1e5, 1e5);
  const double cosines[] = {1e-7, 1 - 1e-7};
  std::vector<Case> cases;
  for (double c : cosines) {
    // Light at cosine c from the normal, distance 2; the view head-on, mirrored, or at 0.6.
    const V3<double> l = at_cosine<double>(c);
    for (const V3<double>& v : {z, at_cosine<double>(c, -1), at_cosine<double>(0.6)}) {
      cases.push_back({"light cosine", V3<double>(0), z, v, 2.0 * l, one});
    }
    // View at cosine c from the normal, light head-on or mirrored.
    const V3<double> v = at_cosine<double>(c);
    cases.push_back({"view cosine", V3<double>(0), z, v, V3<double>(0, 0, 3), one});
    cases.push_back(
        {"view cosine mirrored", V3<double>(0), z, v, 3.0 * at_cosine<double>(c, -1), one});
  }
  cases.push_back({"light on the surface (d = 0)", V3<double>(0.5), z, z, V3<double>(0.5), one});
  for (const V3<double>& att : {one, V3<double>(0, 0, 1), V3<double>(1, 0.1, 0.01)}) {
    cases.push_back(
        {"light at 1e5", V3<double>(0), z, at_cosine<double>(0.6), V3<double>(3e4, 0, 1e5), att});
    cases.push_back({"coordinates 1e5", far_p, z, at_cosine<double>(0.8),
                     far_p + V3<double>(-0.6, 0, 0.8), att});
    cases.push_back({"origin seen from 1e5", V3<double>(0), glm::normalize(V3<double>(1, 1, 1)),
                     glm::normalize(V3<double>(1, 1, 0.5)), V3<double>(1e5, 1e5, 1e5), att});
  }
  const V3<double> l = at_cosine<double>(0.8);
  cases.push_back({"l = -v", V3<double>(0), z, -l, l * 4.0, one});
  cases.push_back({"l = -v, normal towards v", V3<double>(0), -z, -l, l * 4.0, one});
  return cases;
}

template <class T>
void check_terms_finite_non_negative_bounded(PowMode pow) {
  for (const Case& c : extreme_cases()) {
    const V3<T> p(c.p), n(c.n), v(c.v), light(c.light), att(c.att);
    // att of the inputs as T holds them (at 1e5 float moves the light by up to 4e-3).
    const double d = glm::length(V3<double>(light) - V3<double>(p));
    const double bound = 1.0 / (c.att.x + c.att.y * d + c.att.z * d * d);
    for (double alpha : kShininess) {
      for (ShadingModel model : {ShadingModel::phong, ShadingModel::blinn_phong}) {
        const Terms<T> t = terms<T>(p, n, v, light, att, T(alpha), model, pow);
        SCOPED_TRACE(std::string(c.name) + ", alpha " + std::to_string(alpha));
        ASSERT_TRUE(std::isfinite(t.diffuse) && std::isfinite(t.specular));
        EXPECT_GE(t.diffuse, T(0));
        EXPECT_GE(t.specular, T(0));
        // ndl <= 1 and c^alpha <= 1: both terms are at most att (rounding: a few ulp over).
        EXPECT_LE(double(t.diffuse), bound * (1 + 1e-6));
        EXPECT_LE(double(t.specular), bound * (1 + 1e-6));
        if (d == 0.0) {
          EXPECT_EQ(t.diffuse, T(0));  // a light on the surface adds nothing (spec)
          EXPECT_EQ(t.specular, T(0));
        }
      }
    }
  }
}

TEST(Stability, FloatTermsAreFiniteNonNegativeAndBoundedAtTheExtremes) {
  check_terms_finite_non_negative_bounded<float>(PowMode::exact);
}
TEST(Stability, FastPowTermsAreFiniteNonNegativeAndBoundedAtTheExtremes) {
  check_terms_finite_non_negative_bounded<float>(PowMode::fast);
}
TEST(Stability, DoubleTermsAreFiniteNonNegativeAndBoundedAtTheExtremes) {
  check_terms_finite_non_negative_bounded<double>(PowMode::exact);
}

// l = -v leaves no half vector and puts the eye behind the lit side: by the spec's formulas
// c_phong = dot(2 ndl n - l, v) = -(2 ndl^2 - 1) = -0.28 for ndl = 0.8, so no highlight.
TEST(Stability, LightOppositeTheViewGivesNoHighlight) {
  const V3<double> n(0, 0, 1), l = at_cosine<double>(0.8);
  for (double alpha : kShininess) {
    for (ShadingModel model : {ShadingModel::phong, ShadingModel::blinn_phong}) {
      const Terms<float> f =
          terms<float>(V3<float>(0), V3<float>(n), V3<float>(-l), V3<float>(4.0 * l),
                       V3<float>(1, 0, 0), float(alpha), model, PowMode::exact);
      EXPECT_EQ(f.specular, 0.0f) << "alpha " << alpha;
      EXPECT_NEAR(f.diffuse, 0.8f, 1e-6f);
    }
  }
}

// c^alpha for c in (0, 1) decreases as alpha grows (never increases, also after rounding), stays
// in [0, 1], is 1 for c >= 1 and 0 for c <= 0 whatever alpha (alpha = 0 included).
template <class T>
void check_monotone(PowMode pow) {
  const T cosines[] = {T(1e-7), T(0.25),        T(0.5),
                       T(0.9),  T(1) - T(1e-4), T(1) - std::numeric_limits<T>::epsilon()};
  for (T c : cosines) {
    T previous = T(1);
    for (double alpha : kShininess) {
      const T f = specular_power<T>(c, T(alpha), pow);
      EXPECT_LE(f, previous) << "c " << c << " alpha " << alpha;
      EXPECT_GE(f, T(0));
      previous = f;
    }
  }
  for (double alpha : kShininess) {
    EXPECT_EQ(specular_power<T>(T(1), T(alpha), pow), T(1));
    EXPECT_EQ(specular_power<T>(T(0), T(alpha), pow), T(0));
    EXPECT_EQ(specular_power<T>(T(-1e-7), T(alpha), pow), T(0));
  }
  // Strictly on the way: 0.5^1 = 0.5 > 0.5^128 = 2^-128 > 0.5^1000 (0 in float).
  EXPECT_GT(specular_power<T>(T(0.5), T(1), pow), specular_power<T>(T(0.5), T(128), pow));
}

TEST(Stability, SpecularPowerIsMonotoneInShininess) {
  check_monotone<float>(PowMode::exact);
  check_monotone<float>(PowMode::fast);
  check_monotone<double>(PowMode::exact);
  EXPECT_EQ(specular_power<double>(0.5, 128.0), std::ldexp(1.0, -128));
}

// alpha -> 0: c^alpha = exp(alpha ln c) and 1 - exp(-x) <= x, so c^alpha is within alpha |ln c|
// of c^0 = 1; tol adds the rounding of T (and the fast approximation's 2^-23 at the bottom).
template <class T>
void check_continuous_at_zero(PowMode pow, double tol) {
  for (double c : {1e-7, 1e-3, 0.5, 0.999, 1.0 - 1e-7}) {
    const T at_zero = specular_power<T>(T(c), T(0), pow);
    EXPECT_EQ(at_zero, T(1));
    for (double alpha : {1e-8, 1e-4}) {
      const T f = specular_power<T>(T(c), T(alpha), pow);
      EXPECT_NEAR(double(f), double(at_zero), alpha * std::abs(std::log(c)) + tol)
          << "c " << c << " alpha " << alpha;
    }
  }
}

TEST(Stability, SpecularPowerIsContinuousAsShininessGoesToZero) {
  check_continuous_at_zero<float>(PowMode::exact, 1e-7);
  check_continuous_at_zero<float>(PowMode::fast, 3e-7);
  check_continuous_at_zero<double>(PowMode::exact, 1e-15);
}

V3<float> random_unit(std::mt19937& rng) {
  std::normal_distribution<float> normal;
  V3<float> v;
  do {
    v = V3<float>(normal(rng), normal(rng), normal(rng));
  } while (glm::length(v) < 1e-3f);
  return glm::normalize(v);
}

// The spec's tolerance is absolute on values of order 1. With unit attenuation (1, 0, 0) every
// factor compared here (ndl and c^alpha, times att = 1) lies in [0, 1], so an absolute 1e-4 is
// exactly the spec's bound. Both precisions get the same float inputs.
TEST(Stability, FloatAgreesWithDoubleOnAMillionRandomConfigurations) {
  std::mt19937 rng(20240515u);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  double worst_diffuse = 0, worst_specular = 0;
  int over = 0;
  for (int i = 0; i < 1000000; ++i) {
    const V3<float> p(uniform(rng) * 20 - 10, uniform(rng) * 20 - 10, uniform(rng) * 20 - 10);
    const V3<float> light = p + (0.1f + 10.0f * uniform(rng)) * random_unit(rng);
    const V3<float> n = random_unit(rng), v = random_unit(rng);
    const float alpha = 1000.0f * uniform(rng);
    for (ShadingModel model : {ShadingModel::phong, ShadingModel::blinn_phong}) {
      const Terms<float> f =
          terms<float>(p, n, v, light, V3<float>(1, 0, 0), alpha, model, PowMode::exact);
      const Terms<double> d =
          terms<double>(V3<double>(p), V3<double>(n), V3<double>(v), V3<double>(light),
                        V3<double>(1, 0, 0), double(alpha), model, PowMode::exact);
      const double ed = std::abs(double(f.diffuse) - d.diffuse);
      const double es = std::abs(double(f.specular) - d.specular);
      worst_diffuse = std::max(worst_diffuse, ed);
      worst_specular = std::max(worst_specular, es);
      over += ed > 1e-4 || es > 1e-4 ? 1 : 0;
    }
  }
  EXPECT_LE(worst_diffuse, 1e-4);
  EXPECT_LE(worst_specular, 1e-4) << over << " of 2e6 evaluations over 1e-4";
}

}  // namespace
}  // namespace gloss

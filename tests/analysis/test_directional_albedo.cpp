// The directional albedo's quadrature against values derived by hand:
//   - Lambertian: the diffuse term kd ndl is the same in every direction, so its hemisphere
//     integral is kd ndl pi, and over the irradiance pi ndl the albedo is kd at every angle;
//   - Phong at normal incidence: R = n, c = cos theta, so the specular share is
//     (1 / pi) 2 pi integral_0^(pi/2) cos^(a+1) theta sin theta d theta = 2 / (a + 2), and with the
//     energy normalisation (a + 2) / 2pi exactly 1 / pi;
//   - Blinn-Phong at normal incidence: c = cos(theta / 2); with w = cos(theta / 2) the share is
//     8 integral_(1/sqrt 2)^1 w^(a+1) (2 w^2 - 1) dw = 8 ((2 - s) / (a + 4) - (1 - s) / (a + 2)),
//     s = 2^(-(a + 2) / 2) (a = 0 gives 1, as it must: c^0 = 1 everywhere above the surface).
// Each result lies within its stated error (and the error is small) of the hand value.
#include "analysis/lobe/directional_albedo.h"

#include <cmath>

#include <gtest/gtest.h>

namespace gloss {
namespace {

constexpr double kPi = 3.14159265358979323846;

double phong_normal(double a) {
  return 2.0 / (a + 2.0);
}

double blinn_normal(double a) {
  const double s = std::pow(2.0, -(a + 2.0) / 2.0);
  return 8.0 * ((2.0 - s) / (a + 4.0) - (1.0 - s) / (a + 2.0));
}

// |value - expected| within the stated error, with a floor for values exact to rounding.
void expect_within(double value, double expected, double error, const char* what) {
  EXPECT_NEAR(value, expected, std::max(error, 1e-9)) << what << " error " << error;
  EXPECT_LT(error, 1e-4 * std::max(1.0, std::abs(expected))) << what;
}

TEST(DirectionalAlbedo, ALambertianKdGivesKdAtEveryAngle) {
  AlbedoParams p;
  for (double incidence : {0.0, 30.0, 60.0, 85.0}) {
    const AlbedoTerms t = albedo_terms(p, incidence);
    expect_within(t.diffuse, 1.0, t.diffuse_error, "diffuse share");
    Material m;
    m.diffuse = glm::vec3(0.2f, 0.5f, 0.8f);
    m.specular = glm::vec3(0.0f);
    const glm::dvec3 a = directional_albedo(m, t, ShadingModel::phong);
    EXPECT_NEAR(a.x, 0.2, 1e-6) << incidence;
    EXPECT_NEAR(a.z, 0.8, 1e-6) << incidence;
  }
}

TEST(DirectionalAlbedo, PhongAtNormalIncidenceIsTwoOverAlphaPlusTwo) {
  for (double a : {0.0, 1.0, 10.0, 51.2, 1000.0, 1e5}) {
    AlbedoParams p;
    p.phong_alpha = a;
    const AlbedoTerms t = albedo_terms(p, 0.0);
    expect_within(t.phong, phong_normal(a), t.phong_error, "Phong");
    p.energy_normalize = true;  // (a + 2) / 2pi: exactly 1 / pi
    const AlbedoTerms n = albedo_terms(p, 0.0);
    expect_within(n.phong, 1.0 / kPi, n.phong_error, "normalised Phong");
  }
}

TEST(DirectionalAlbedo, BlinnPhongAtNormalIncidenceHasItsClosedForm) {
  EXPECT_NEAR(blinn_normal(0.0), 1.0, 1e-15);  // the formula itself
  for (double a : {0.0, 4.0, 40.0, 204.8, 4000.0}) {
    AlbedoParams p;
    p.blinn_alpha = a;
    const AlbedoTerms t = albedo_terms(p, 0.0);
    expect_within(t.blinn, blinn_normal(a), t.blinn_error, "Blinn-Phong");
  }
}

// Phong with alpha = 0 sends c^0 = 1 into every direction with R . v > 0 and n . v > 0. The
// integral of n . v over that part of the hemisphere is its projection onto the surface: the half
// disc on R's side (pi / 2) and, on the light's side, half of the ellipse the great circle
// perpendicular to R projects to (semi-axes 1 and cos theta_i: pi cos theta_i / 2). Over the
// irradiance pi cos theta_i: (1 + cos theta_i) / (2 cos theta_i), 1.5 at 60 degrees: classic
// Phong's specular reflects more than it receives towards grazing incidence.
TEST(DirectionalAlbedo, FlatPhongAtObliqueIncidenceIsTheProjectedLune) {
  AlbedoParams p;
  p.phong_alpha = 0.0;
  for (double incidence : {30.0, 60.0, 80.0}) {
    const AlbedoTerms t = albedo_terms(p, incidence);
    const double c = std::cos(incidence * kPi / 180.0);
    expect_within(t.phong, (1.0 + c) / (2.0 * c), t.phong_error, "alpha 0");
  }
  const std::vector<AlbedoTerms> curve = albedo_curve(p, 10, 81.0);
  ASSERT_EQ(curve.size(), 10u);
  EXPECT_EQ(curve.front().incidence_deg, 0.0);
  EXPECT_EQ(curve.back().incidence_deg, 81.0);
  EXPECT_EQ(curve[3].incidence_deg, 27.0);
}

}  // namespace
}  // namespace gloss

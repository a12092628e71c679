// The pairs' quadrature (physical/lobe_samples.h) against integrals known in closed form.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "physical/lobe_samples.h"
#include "physical/microfacet.h"

namespace gloss {
namespace {

// Every pair has both directions above the surface and v is l mirrored about the half vector.
TEST(LobeSamples, PairsAreAboveTheSurfaceAndMirrorAboutH) {
  const LobeSamples s = make_lobe_samples(LobeGrid{});
  ASSERT_GT(s.pairs.size(), 10000u);
  for (const LobePair& p : s.pairs) {
    ASSERT_GT(p.l.z, 0.0);
    ASSERT_GT(p.v.z, 0.0);
    ASSERT_GT(p.weight, 0.0);
    const glm::dvec3 h = glm::normalize(p.l + p.v);
    ASSERT_NEAR(h.z, p.angles.cos_h, 1e-12);
    ASSERT_NEAR(p.cos_blinn, p.angles.cos_h, 1e-12);
    // R . V = 2 (n.l)(n.v) - l.v
    ASSERT_NEAR(p.cos_phong, 2.0 * p.l.z * p.v.z - glm::dot(p.l, p.v), 1e-12);
  }
}

// The measure of the pairs: integral over both hemispheres of d(omega_l) d(omega_v) = (2 pi)^2,
// and of cos(theta_l) d(omega_l) d(omega_v) = pi * 2 pi, for a broad and a narrow grid.
TEST(LobeSamples, WeightsIntegrateTheHemispherePairs) {
  for (double width : {1.0, 0.3, 0.01}) {
    LobeGrid g;
    g.width = width;
    g.max_angle_deg = 90.0;
    const LobeSamples s = make_lobe_samples(g);
    double cos_l = 0.0, cos_lv = 0.0;
    for (const LobePair& p : s.pairs) {
      cos_l += p.weight * p.l.z;
      cos_lv += p.weight * p.l.z * p.v.z;
    }
    EXPECT_NEAR(s.total_weight / (4.0 * kPi * kPi), 1.0, 5e-3) << "width " << width;
    EXPECT_NEAR(cos_l / (2.0 * kPi * kPi), 1.0, 5e-3) << "width " << width;
    EXPECT_NEAR(cos_lv / (kPi * kPi), 1.0, 5e-3) << "width " << width;  // pi * pi
  }
}

// Without the rims: both directions within 80 degrees of the normal, (2 pi (1 - cos 80))^2.
TEST(LobeSamples, GrazingPairsLeftOut) {
  const LobeSamples s = make_lobe_samples(LobeGrid{});
  const double cos80 = std::cos(80.0 * kPi / 180.0);
  for (const LobePair& p : s.pairs) {
    ASSERT_GT(p.l.z, cos80);
    ASSERT_GT(p.v.z, cos80);
  }
  const double cap = 2.0 * kPi * (1.0 - cos80);
  EXPECT_NEAR(s.total_weight / (cap * cap), 1.0, 1e-2);
}

}  // namespace
}  // namespace gloss

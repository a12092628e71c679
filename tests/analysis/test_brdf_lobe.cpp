// The lobe view's samples (analysis/lobe/brdf_lobe.h) against values worked out by hand from
// docs/spec/shading.md. Frame: n = +y, light from the left at elevation e, outgoing angle theta
// from the normal, positive on the mirror side.
#include "analysis/lobe/brdf_lobe.h"

#include <cmath>

#include <gtest/gtest.h>

namespace gloss {
namespace {

constexpr double kPi = 3.14159265358979323846;

Material grey(float kd, float ks, float alpha) {
  Material m;
  m.diffuse = glm::vec3(kd);
  m.specular = glm::vec3(ks);
  m.shininess = alpha;
  return m;
}

LobeParams params(double elevation, double phong_alpha, double blinn_alpha, bool energy) {
  LobeParams p;
  p.elevation_deg = elevation;
  p.phong_alpha = phong_alpha;
  p.blinn_alpha = blinn_alpha;
  p.energy_normalize = energy;
  return p;
}

// At the mirror direction (theta = 90 - e) R = V, so c = 1 and c^alpha = 1 for any alpha: the
// Phong specular is ks. The diffuse floor is kd * ndl = kd * sin(e): 0.5 * sin 30 = 0.25.
TEST(BrdfLobe, PhongAtTheMirrorDirectionIsKs) {
  const LobeSample s = lobe_sample(grey(0.5f, 0.75f, 1.0f), params(30, 1, 1, false), 60.0);
  EXPECT_NEAR(s.cos_phong, 1.0, 1e-12);
  EXPECT_NEAR(s.phong.x, 0.75, 1e-12);
  EXPECT_NEAR(s.diffuse.y, 0.25, 1e-7);
}

// alpha = 1, e = 45 (R at theta = 45), looking along the normal (theta = 0): c = cos 45.
// Blinn-Phong there: H bisects l (45 degrees from n) and v = n, so N . H = cos 22.5.
TEST(BrdfLobe, AlongTheNormalAtElevation45) {
  const LobeSample s = lobe_sample(grey(0.0f, 1.0f, 1.0f), params(45, 1, 1, false), 0.0);
  EXPECT_NEAR(s.cos_phong, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(s.phong.x, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(s.cos_blinn, std::cos(22.5 * kPi / 180.0), 1e-12);
  EXPECT_NEAR(s.blinn.x, std::cos(22.5 * kPi / 180.0), 1e-12);
}

// Looking back at the light (theta = -45 at e = 45): V = L, so H = L and N . H = cos 45, while
// R is 90 degrees from V: Phong c = 0, nothing. Blinn at alpha 2: cos^2 45 = 0.5, times ks 0.8.
TEST(BrdfLobe, BackTowardsTheLightHalfVectorIsTheLight) {
  const LobeSample s = lobe_sample(grey(0.0f, 0.8f, 2.0f), params(45, 2, 2, false), -45.0);
  EXPECT_NEAR(s.cos_blinn, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(s.blinn.x, 0.4, 1e-7);
  EXPECT_NEAR(s.cos_phong, 0.0, 1e-12);
  EXPECT_EQ(s.phong.x, 0.0);
}

// Energy normalisation: Phong (alpha + 2) / (2 pi) = 3 / (2 pi) at alpha 1; Blinn-Phong
// (alpha + 8) / (8 pi) = 16 / (8 pi) = 2 / pi at alpha 8. At the mirror both cosines are 1.
TEST(BrdfLobe, EnergyFactors) {
  const BrdfLobe lobe = sample_brdf_lobe(grey(0.0f, 1.0f, 1.0f), params(60, 1, 8, true));
  EXPECT_NEAR(lobe.phong_norm, 3.0 / (2.0 * kPi), 1e-12);
  EXPECT_NEAR(lobe.blinn_norm, 2.0 / kPi, 1e-12);
  const LobeSample mirror = lobe_sample(grey(0.0f, 1.0f, 1.0f), params(60, 1, 8, true), 30.0);
  EXPECT_NEAR(mirror.phong.x, 3.0 / (2.0 * kPi), 1e-12);
  EXPECT_NEAR(mirror.blinn.x, 2.0 / kPi, 1e-12);
}

// 181 samples from -90 to 90 one degree apart; the diffuse floor is the same everywhere, and a
// coloured ks keeps its colour.
TEST(BrdfLobe, SamplesSpanTheHalfPlane) {
  Material m = grey(0.4f, 1.0f, 10.0f);
  m.specular = {1.0f, 0.5f, 0.25f};
  const BrdfLobe lobe = sample_brdf_lobe(m, params(90, 10, 10, false));
  ASSERT_EQ(lobe.samples.size(), 181u);
  EXPECT_DOUBLE_EQ(lobe.samples.front().theta_deg, -90.0);
  EXPECT_DOUBLE_EQ(lobe.samples[90].theta_deg, 0.0);
  EXPECT_DOUBLE_EQ(lobe.samples.back().theta_deg, 90.0);
  for (const LobeSample& s : lobe.samples) EXPECT_NEAR(s.diffuse.x, 0.4, 1e-7);
  // Overhead light, view along the normal: the mirror direction, c = 1.
  EXPECT_NEAR(lobe.samples[90].phong.y, 0.5, 1e-12);
  EXPECT_NEAR(lobe.samples[90].phong.z, 0.25, 1e-12);
  // 60 degrees off: Phong c = cos 60 = 0.5, 0.5^10 = 1/1024.
  EXPECT_NEAR(lobe.samples[150].phong.x, 1.0 / 1024.0, 1e-12);
}

TEST(BrdfLobe, LuminanceWeights) {
  EXPECT_NEAR(luminance({1, 1, 1}), 1.0, 1e-12);
  EXPECT_NEAR(luminance({0, 1, 0}), 0.7152, 1e-12);
}

// The reference curve is the reference path's pi f(l, v) ndl. Head-on light (e = 90) seen along
// the normal: h = n, n.l = n.v = v.h = 1, G2 = 1, F = F0, D = 1 / (pi a^2), so
// pi f ndl = pi F0 / (4 pi a^2) = F0 / (4 a^2); gold at roughness 0.5 (a = 0.25): 4 F0.
TEST(BrdfLobe, ReferenceCurveHeadOn) {
  Material m = grey(0.0f, 1.0f, 10.0f);
  PhysicalReference gold;
  gold.roughness = 0.5f;
  m.reference = gold;
  const BrdfLobe lobe = sample_brdf_lobe(m, params(90, 10, 40, false));
  EXPECT_TRUE(lobe.has_reference);
  const LobeSample s = lobe_sample(m, params(90, 10, 40, false), 0.0);
  EXPECT_NEAR(s.reference.x, 4.0 * 1.0, 1e-9);
  EXPECT_NEAR(s.reference.y, 4.0 * 0.782, 1e-9);
  EXPECT_NEAR(s.reference.z, 4.0 * 0.344, 1e-9);
  // Nothing below the horizon, and no curve without a reference.
  EXPECT_EQ(lobe_sample(m, params(0, 10, 40, false), 30.0).reference, glm::dvec3(0.0));
  EXPECT_FALSE(sample_brdf_lobe(grey(0.5f, 0.5f, 10.0f), params(45, 10, 40, false)).has_reference);
}

}  // namespace
}  // namespace gloss

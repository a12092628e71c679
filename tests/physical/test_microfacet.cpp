// The reference's terms (physical/microfacet.h, physical/reference_brdf.h) at angles worked out
// by hand from docs/spec/physical-reference.md's formulas; the arithmetic is in the comments.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "physical/measured_metals.h"
#include "physical/microfacet.h"
#include "physical/reference_brdf.h"

namespace gloss {
namespace {

const glm::dvec3 kNormal(0.0, 0.0, 1.0);

// D(h) = a^2 / (pi ((n.h)^2 (a^2 - 1) + 1)^2)
TEST(Microfacet, GgxDistributionByHand) {
  // a = 0.25, n.h = 1: a^2 / (pi a^4) = 1 / (pi 0.0625) = 16 / pi = 5.0929582
  EXPECT_NEAR(ggx_distribution(1.0, 0.25), 16.0 / kPi, 1e-12);
  // a = 0.5, n.h = 0.8: 0.64 (0.25 - 1) + 1 = 0.52; 0.52^2 = 0.2704;
  // 0.25 / (pi 0.2704) = 0.25 / 0.84948665 = 0.29429538
  EXPECT_NEAR(ggx_distribution(0.8, 0.5), 0.29429538, 1e-8);
  // a = 1: (n.h)^2 0 + 1 = 1 for every h, D = 1 / pi
  EXPECT_NEAR(ggx_distribution(0.3, 1.0), 1.0 / kPi, 1e-12);
  // The sine form agrees: n.h = 0.8 is sin = 0.6.
  EXPECT_NEAR(ggx_distribution(0.8, 0.6, 0.5), 0.29429538, 1e-8);
  // The mirror limit stays finite: a = 1e-90, n.h = 1 gives 1 / (pi 1e-180).
  EXPECT_NEAR(ggx_distribution(1.0, 0.0, 1e-90) * kPi * 1e-180, 1.0, 1e-12);
}

// Lambda = (sqrt(1 + a^2 tan^2) - 1) / 2, G2 = 1 / (1 + Lambda(l) + Lambda(v))
TEST(Microfacet, SmithG2ByHand) {
  // a = 0.5, cos = 0.6: tan^2 = 0.64 / 0.36 = 16/9; a^2 tan^2 = 4/9;
  // sqrt(13/9) = 1.2018504; Lambda = 0.2018504 / 2 = 0.1009252
  EXPECT_NEAR(smith_lambda(0.6, 0.5), 0.10092521, 1e-8);
  // cos = 0.8: tan^2 = 9/16; a^2 tan^2 = 9/64; sqrt(73/64) = 1.0680005; Lambda = 0.0340002
  EXPECT_NEAR(smith_lambda(0.8, 0.5), 0.03400023, 1e-8);
  // G2 = 1 / (1 + 0.1009252 + 0.0340002) = 1 / 1.1349254 = 0.8811151
  EXPECT_NEAR(smith_g2(0.6, 0.8, 0.5), 0.88111515, 1e-8);
  // Head-on light and view: tan = 0, Lambda = 0, G2 = 1.
  EXPECT_EQ(smith_g2(1.0, 1.0, 0.7), 1.0);
  // Grazing: Lambda grows as a / (2 cos): cos = 1e-7, a = 0.5 gives 2.5e6 (to 1e-6 relative).
  EXPECT_NEAR(smith_lambda(1e-7, 0.5) / 2.5e6, 1.0, 1e-6);
}

// F = F0 + (1 - F0) (1 - v.h)^5
TEST(Microfacet, SchlickFresnelByHand) {
  // F0 = 0.04, v.h = 0.5: 0.5^5 = 1/32; 0.04 + 0.96 / 32 = 0.04 + 0.03 = 0.07
  EXPECT_NEAR(schlick_fresnel(glm::dvec3(0.04), 0.5).x, 0.07, 1e-15);
  // Gold at v.h = 1 is its F0; at v.h = 0 every channel is 1.
  const glm::dvec3 gold = reference_f0(ReferenceKind::gold);
  EXPECT_EQ(schlick_fresnel(gold, 1.0), gold);
  EXPECT_EQ(schlick_fresnel(gold, 0.0), glm::dvec3(1.0));
}

// The measured table as the spec lists it (Real-Time Rendering, 4th ed., Table 9.2).
TEST(Microfacet, MeasuredF0IsTheSpecsTable) {
  EXPECT_EQ(reference_f0(ReferenceKind::gold), glm::dvec3(1.000, 0.782, 0.344));
  EXPECT_EQ(reference_f0(ReferenceKind::silver), glm::dvec3(0.972, 0.960, 0.915));
  EXPECT_EQ(reference_f0(ReferenceKind::aluminium), glm::dvec3(0.913, 0.922, 0.924));
  EXPECT_EQ(reference_f0(ReferenceKind::copper), glm::dvec3(0.955, 0.638, 0.538));
  EXPECT_EQ(reference_f0(ReferenceKind::chromium), glm::dvec3(0.549, 0.556, 0.554));
  EXPECT_EQ(reference_f0(ReferenceKind::brass), glm::dvec3(0.910, 0.778, 0.423));
  EXPECT_EQ(reference_f0(ReferenceKind::dielectric), glm::dvec3(0.04));
}

ReferenceBrdf dielectric(double a, double base) {
  ReferenceBrdf b;
  b.f0 = glm::dvec3(0.04);
  b.base = glm::dvec3(base);
  b.a = a;
  b.dielectric = true;
  return b;
}

// The whole BRDF, symmetric case: a = 0.5, l and v 60 degrees either side of n in one plane, so
// h = n, n.l = n.v = v.h = 0.5.
//   D = 1 / (pi a^2) = 4 / pi = 1.2732395
//   tan^2(60) = 3, a^2 tan^2 = 0.75, Lambda = (sqrt(1.75) - 1) / 2 = 0.1614378,
//   G2 = 1 / 1.3228757 = 0.7559289
//   F = 0.07 (above); f_spec = D G2 F / (4 0.5 0.5) = 1.2732395 0.7559289 0.07 = 0.0673735
//   diffuse = (1 - 0.07) base / pi = 0.93 0.5 / pi = 0.1480141
TEST(ReferenceBrdf, SymmetricPairByHand) {
  const double s = std::sqrt(3.0) / 2.0;
  const glm::dvec3 l(s, 0.0, 0.5), v(-s, 0.0, 0.5);
  const BrdfValue f = evaluate_brdf(dielectric(0.5, 0.5), kNormal, l, v);
  EXPECT_NEAR(f.specular.x, 0.0673735, 1e-7);
  EXPECT_NEAR(f.diffuse.x, 0.1480141, 1e-7);
  EXPECT_NEAR(f.specular.z, f.specular.x, 1e-15);
}

// An asymmetric pair tells Fresnel at v.h from Fresnel at n.l: a = 0.5, l 60 degrees from n,
// v = n. |l + v| = sqrt(0.75 + 2.25) = sqrt(3), h = (0.5, 0, 0.8660254): n.h = v.h = cos 30.
//   D: 0.75 (0.25 - 1) + 1 = 0.4375; 0.25 / (pi 0.4375^2) = 0.4157517
//   G2 = 1 / (1 + Lambda(0.5) + Lambda(1)) = 1 / 1.1614378 = 0.8610017
//   F(v.h): (1 - 0.8660254)^5 = 0.1339746^5 = 4.31631e-5; 0.04 + 0.96 4.31631e-5 = 0.0400414
//   f_spec = D G2 F / (4 0.5 1) = 0.4157517 0.8610017 0.0400414 / 2 = 0.0071667
// (Fresnel at n.l = 0.5 would give F = 0.07 and f_spec = 0.0125287.)
TEST(ReferenceBrdf, AsymmetricPairByHand) {
  const glm::dvec3 l(std::sqrt(3.0) / 2.0, 0.0, 0.5), v = kNormal;
  const BrdfValue f = evaluate_brdf(dielectric(0.5, 0.0), kNormal, l, v);
  EXPECT_NEAR(f.specular.y, 0.0071667, 1e-7);
  EXPECT_EQ(f.diffuse, glm::dvec3(0.0));
}

// Nothing below the horizon, on either side.
TEST(ReferenceBrdf, ZeroBelowTheHorizon) {
  const ReferenceBrdf b = dielectric(0.3, 0.8);
  const glm::dvec3 up = glm::normalize(glm::dvec3(0.3, 0.0, 1.0));
  const glm::dvec3 down(0.6, 0.0, -0.8);
  EXPECT_EQ(evaluate_brdf(b, kNormal, down, up).total(), glm::dvec3(0.0));
  EXPECT_EQ(evaluate_brdf(b, kNormal, up, down).total(), glm::dvec3(0.0));
  EXPECT_EQ(evaluate_brdf(b, kNormal, up, -up).total(), glm::dvec3(0.0));
}

// A material's reference block gives the BRDF: a = roughness^2, the table's F0, and a base only
// for the dielectric.
TEST(ReferenceBrdf, FromTheDocument) {
  PhysicalReference r;
  r.kind = ReferenceKind::copper;
  r.roughness = 0.5f;
  r.base = glm::vec3(0.2f);
  ReferenceBrdf b = make_reference_brdf(r);
  EXPECT_EQ(b.a, 0.25);
  EXPECT_EQ(b.f0, reference_f0(ReferenceKind::copper));
  EXPECT_EQ(b.base, glm::dvec3(0.0));
  EXPECT_FALSE(b.dielectric);
  r.kind = ReferenceKind::dielectric;
  b = make_reference_brdf(r);
  EXPECT_EQ(b.f0, glm::dvec3(0.04));
  EXPECT_EQ(b.base, glm::dvec3(glm::vec3(0.2f)));
  EXPECT_TRUE(b.dielectric);
}

}  // namespace
}  // namespace gloss

// The fits "the other way" (physical/metal_rough_fit.h, physical/threejs_phong_fit.h): glTF's
// metallic-roughness lobe and three.js's Phong lobe by hand, against the reference BRDF they
// share terms with, self-recovery, and the Phong -> metallic-roughness -> Phong round trip.
#include <cmath>

#include <gtest/gtest.h>

#include "physical/metal_rough_fit.h"
#include "physical/microfacet.h"
#include "physical/phong_fit.h"
#include "physical/reference_brdf.h"
#include "physical/threejs_phong_fit.h"

namespace gloss {
namespace {

// Light and view both along the normal: v.h = 1, n.h = 1.
LobePair head_on() {
  LobePair p;
  p.angles = pair_cosines({0, 0, 1}, {0, 0, 1}, {0, 0, 1});
  p.cos_phong = p.cos_blinn = 1.0;
  return p;
}

// Head-on, D = 1 / (pi a^2), G2 = 1, F = F0: a conductor sends pi (F0 / (4 pi a^2)) = F0 / (4 a^2);
// a dielectric 0.04 / (4 a^2) + (1 - 0.04) base. Roughness 0.5: a = 0.25, 4 a^2 = 0.25.
TEST(MetalRough, HeadOnByHand) {
  MetalRough metal{{1.0, 0.5, 0.25}, 1.0, 0.5};
  const glm::dvec3 m = metal_rough_radiance(metal, head_on());
  EXPECT_NEAR(m.x, 4.0, 1e-12);
  EXPECT_NEAR(m.y, 2.0, 1e-12);
  EXPECT_NEAR(m.z, 1.0, 1e-12);
  MetalRough plastic{{0.5, 0.0, 1.0}, 0.0, 0.5};
  const glm::dvec3 d = metal_rough_radiance(plastic, head_on());
  EXPECT_NEAR(d.x, 0.16 + 0.96 * 0.5, 1e-12);
  EXPECT_NEAR(d.y, 0.16, 1e-12);
  EXPECT_NEAR(d.z, 0.16 + 0.96, 1e-12);
  // Half metal: F0 = 0.5 (0.04 + base), the diffuse halved.
  MetalRough half{{0.5, 0.5, 0.5}, 0.5, 0.5};
  EXPECT_NEAR(metal_rough_radiance(half, head_on()).x, 0.5 * (0.04 + 0.5) * 4.0 + 0.5 * 0.96 * 0.5,
              1e-12);
}

// metallic 1 is the reference's conductor of F0 = base; metallic 0 its dielectric: over every
// pair of a grid, to rounding.
TEST(MetalRough, EndsAreTheReferenceBrdf) {
  const LobeSamples samples = make_lobe_samples({});
  ReferenceBrdf conductor = conductor_brdf({0.9, 0.6, 0.3}, 0.35);
  ReferenceBrdf dielectric;
  dielectric.dielectric = true;
  dielectric.base = {0.2, 0.5, 0.7};
  dielectric.a = 0.6 * 0.6;
  const MetalRough metal{conductor.f0, 1.0, 0.35}, plastic{dielectric.base, 0.0, 0.6};
  for (std::size_t i = 0; i < samples.pairs.size(); i += 97) {
    const LobePair& p = samples.pairs[i];
    const glm::dvec3 a = metal_rough_radiance(metal, p), b = reference_radiance(conductor, p);
    const glm::dvec3 c = metal_rough_radiance(plastic, p), d = reference_radiance(dielectric, p);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(a[k], b[k], 1e-12 * std::max(1.0, b[k]));
      EXPECT_NEAR(c[k], d[k], 1e-12 * std::max(1.0, d[k]));
    }
  }
}

// A lobe made by a metallic-roughness material gives that material back.
TEST(MetalRough, RecoversItsOwnLobe) {
  const MetalRough cases[] = {
      {{1.0, 0.782, 0.344}, 1.0, 0.4}, {{0.5, 0.2, 0.1}, 0.0, 0.6}, {{0.8, 0.8, 0.3}, 0.5, 0.15}};
  for (const MetalRough& want : cases) {
    LobeGrid grid;
    grid.width = lobe_width_for_ggx(want.roughness * want.roughness);
    const LobeSamples samples = make_lobe_samples(grid);
    const MetalRoughFit fit =
        fit_metal_rough_lobe(samples, sample_metal_rough(want, samples), LobeMetric::l2);
    SCOPED_TRACE("metallic " + std::to_string(want.metallic));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(fit.material.base_colour[c], want.base_colour[c], 1e-3);
    EXPECT_NEAR(fit.material.metallic, want.metallic, 1e-3);
    EXPECT_NEAR(fit.material.roughness / want.roughness, 1.0, 1e-3);
    EXPECT_LT(fit.residual.l2_relative, 1e-4);
  }
}

// Phong -> metallic-roughness -> Phong. The second fit could have given the first lobe back (it
// is one of its candidates), so the round trip's error is at most twice the first fit's
// (triangle inequality); a GGX lobe is no Phong lobe, so the first fit's error is above zero.
TEST(MetalRough, RoundTripBoundedByTwiceTheFit) {
  PhongLobe gold;
  gold.kd = {0.1, 0.07, 0.03};
  gold.ks = {0.9, 0.7, 0.3};
  gold.alpha = 51.2;
  const LobeGrid grid = grid_for_phong(gold);
  const LobeSamples samples = make_lobe_samples(grid);
  const SampledLobe source = sample_phong(gold, samples);
  const MetalRoughFit pbr = fit_metal_rough_lobe(samples, source, LobeMetric::l2);
  EXPECT_GT(pbr.residual.l2_relative, 1e-3);
  FitOptions options;
  const PhongFit back = fit_phong_lobe(samples, sample_metal_rough(pbr.material, samples), options);
  const LobeResidual trip = lobe_residual(samples, source, sample_phong(back.lobe, samples));
  EXPECT_LE(trip.l2, 2.0 * pbr.residual.l2 * (1.0 + 1e-6));
  // A metal's lobe: mostly metallic, the highlight's colour order kept.
  EXPECT_GT(pbr.material.metallic, 0.5);
  EXPECT_GT(pbr.material.base_colour.r, pbr.material.base_colour.g);
  EXPECT_GT(pbr.material.base_colour.g, pbr.material.base_colour.b);
}

// A Phong lobe fitted to GGX gold and fitted back lands near gold: F0 and roughness within the
// loose bounds of a lobe that was only approximately GGX.
TEST(MetalRough, GoldThroughPhongAndBack) {
  PhysicalReference gold;
  gold.kind = ReferenceKind::gold;
  gold.roughness = 0.3f;
  const PhongFit phong = fit_phong_to_reference(gold, {});
  const MetalRoughFit back = fit_metal_rough(phong.lobe);
  EXPECT_GT(back.material.metallic, 0.8);
  EXPECT_NEAR(back.material.roughness, 0.3, 0.3 * 0.25);
  EXPECT_NEAR(back.material.base_colour.r, 1.0, 0.15);
  EXPECT_NEAR(back.material.base_colour.b, 0.344, 0.15);
}

// three.js, head-on: n.l = 1, v.h = 1, Fresnel weight 2^(-5.55473 - 6.98316) = 2^-12.53789;
// radiance = color + (specular + (1 - specular) w) (s / 2 + 1) / 4.
TEST(ThreePhong, HeadOnByHand) {
  const double w = std::pow(2.0, -12.53789);
  EXPECT_NEAR(threejs_fresnel_weight(1.0), w, 1e-15);
  EXPECT_NEAR(threejs_fresnel_weight(0.0), 1.0, 0.0);
  const ThreePhong m{{0.2, 0.4, 0.6}, {0.5, 0.0, 1.0}, 30.0};
  const glm::dvec3 r = threejs_phong_radiance(m, head_on());
  EXPECT_NEAR(r.x, 0.2 + (0.5 + 0.5 * w) * 4.0, 1e-12);
  EXPECT_NEAR(r.y, 0.4 + w * 4.0, 1e-12);
  EXPECT_NEAR(r.z, 0.6 + 4.0, 1e-12);
}

TEST(ThreePhong, RecoversItsOwnLobe) {
  const ThreePhong want{{0.3, 0.2, 0.1}, {0.05, 0.4, 0.9}, 120.0};
  LobeGrid grid;
  grid.width = lobe_width_for_exponent(want.shininess);
  const LobeSamples samples = make_lobe_samples(grid);
  const ThreePhongFit fit =
      fit_threejs_phong_lobe(samples, sample_threejs_phong(want, samples), LobeMetric::l2);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(fit.material.color[c], want.color[c], 1e-4);
    EXPECT_NEAR(fit.material.specular[c], want.specular[c], 1e-4);
  }
  EXPECT_NEAR(fit.material.shininess / want.shininess, 1.0, 1e-3);
}

// gloss Blinn-Phong ks (n.h)^alpha against three.js's n.l F (s / 2 + 1) / 4 (n.h)^s: where the
// Fresnel weight is small (most pairs) the closest three.js lobe has s near alpha and
// specular near ks 4 / (alpha / 2 + 1); three.js's extra n.l (<= 1) only lowers its lobe, so
// the fit's specular is above that and within 35 % of it; the diffuse colour is kd.
TEST(ThreePhong, BlinnPhongMapsToNormalisedSpecular) {
  PhongLobe blinn;
  blinn.model = ShadingModel::blinn_phong;
  blinn.kd = {0.5, 0.3, 0.2};
  blinn.ks = {0.5, 0.5, 0.5};
  blinn.alpha = 100.0;
  const ThreePhongFit fit = fit_threejs_phong(blinn);
  const double want = 0.5 * 4.0 / 51.0;
  EXPECT_GT(fit.material.specular.x, want);
  EXPECT_LT(fit.material.specular.x, 1.35 * want);
  EXPECT_NEAR(fit.material.shininess / 100.0, 1.0, 0.15);
  EXPECT_NEAR(fit.material.color.x, 0.5, 0.02);
  EXPECT_NEAR(fit.material.color.z, 0.2, 0.02);
}

}  // namespace
}  // namespace gloss

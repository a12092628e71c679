// The fit (physical/phong_fit.h): self-recovery of Phong and Blinn-Phong lobes, Blinn-Phong
// against Beckmann (Walter et al. 2007), the GGX residual that no Phong lobe removes, model to
// model (the 4x exponent rule), determinism.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "physical/microfacet.h"
#include "physical/phong_fit.h"

namespace gloss {
namespace {

void expect_relative(const glm::dvec3& got, const glm::dvec3& want, double tolerance,
                     const char* what) {
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(got[c] / want[c], 1.0, tolerance) << what << " channel " << c;
  }
}

struct Recovery {
  ShadingModel model;
  bool energy;
  LobeMetric metric;
  double alpha;
};

// Data made by a Phong or Blinn-Phong lobe gives back its own kd, ks (1e-3 relative) and alpha
// (1 %), in either metric, with the energy switch off or on.
TEST(PhongFit, RecoversItsOwnLobe) {
  const Recovery cases[] = {
      {ShadingModel::phong, false, LobeMetric::l2, 40.0},
      {ShadingModel::phong, true, LobeMetric::l2, 7.0},
      {ShadingModel::phong, false, LobeMetric::lightness, 400.0},
      {ShadingModel::blinn_phong, false, LobeMetric::l2, 200.0},
      {ShadingModel::blinn_phong, true, LobeMetric::lightness, 12.0},
      {ShadingModel::blinn_phong, false, LobeMetric::l2, 5000.0},
  };
  for (const Recovery& c : cases) {
    PhongLobe source;
    source.kd = {0.3, 0.2, 0.1};
    source.ks = {0.5, 0.6, 0.7};
    source.alpha = c.alpha;
    source.model = c.model;
    source.energy_normalize = c.energy;
    FitOptions options;
    options.model = c.model;
    options.energy_normalize = c.energy;
    options.metric = c.metric;
    const PhongFit fit = fit_phong_to_phong(source, options);
    SCOPED_TRACE(std::string(to_string(c.model)) + " alpha " + std::to_string(c.alpha) +
                 " energy " + std::to_string(c.energy) + " " + to_string(c.metric));
    expect_relative(fit.lobe.kd, source.kd, 1e-3, "kd");
    expect_relative(fit.lobe.ks, source.ks, 1e-3, "ks");
    EXPECT_NEAR(fit.lobe.alpha / source.alpha, 1.0, 1e-2);
    EXPECT_LT(fit.residual.l2_relative, 1e-4);
  }
}

// Beckmann's distribution of slope m, D_B = exp(-tan^2 / m^2) / (pi m^2 cos^4), as a lobe of the
// half vector alone: the best Blinn-Phong exponent is within 10 % of 2 / m^2 - 2 (Walter et al.
// 2007, "Microfacet models for refraction through rough surfaces", eq. 30) for m <= 0.3.
TEST(PhongFit, BlinnPhongAgainstBeckmann) {
  for (double m : {0.05, 0.1, 0.2, 0.3}) {
    LobeGrid grid;
    grid.width = m;
    const LobeSamples samples = make_lobe_samples(grid);
    SampledLobe target;
    for (const LobePair& p : samples.pairs) {
      const double c = p.angles.cos_h, s = p.angles.sin_h;
      const double tan2 = (s * s) / (c * c);
      target.push_back(glm::dvec3(std::exp(-tan2 / (m * m)) / (kPi * m * m * c * c * c * c)));
    }
    FitOptions options;
    options.model = ShadingModel::blinn_phong;
    const PhongFit fit = fit_phong_lobe(samples, target, options);
    const double walter = 2.0 / (m * m) - 2.0;
    std::printf("Beckmann m %.2f: best Blinn-Phong alpha %.2f, 2/m^2 - 2 = %.2f (ratio %.4f)\n", m,
                fit.lobe.alpha, walter, fit.lobe.alpha / walter);
    EXPECT_NEAR(fit.lobe.alpha / walter, 1.0, 0.10) << "m " << m;
  }
}

// GGX cannot be matched by one Phong or Blinn-Phong lobe: the residual stays well above zero,
// and what the fit reports is the residual of the lobe it returns.
TEST(PhongFit, GgxResidualIsReported) {
  PhysicalReference gold;
  gold.roughness = 0.3f;
  for (ShadingModel model : {ShadingModel::phong, ShadingModel::blinn_phong}) {
    FitOptions options;
    options.model = model;
    const PhongFit fit = fit_phong_to_reference(gold, options);
    EXPECT_GT(fit.residual.l2_relative, 0.05) << to_string(model);
    EXPECT_GT(fit.residual.lightness, 1.0) << to_string(model);
    const LobeResidual again = phong_residual(fit.lobe, gold);
    EXPECT_DOUBLE_EQ(again.l2, fit.residual.l2);
    EXPECT_DOUBLE_EQ(again.lightness, fit.residual.lightness);
  }
}

// The same request twice gives the same constants, bit for bit, on any number of threads.
TEST(PhongFit, Deterministic) {
  PhysicalReference r;
  r.kind = ReferenceKind::dielectric;
  r.base = {0.6f, 0.1f, 0.1f};
  r.roughness = 0.4f;
  FitOptions options;
  options.metric = LobeMetric::lightness;
  const PhongFit a = fit_phong_to_reference(r, options);
  const PhongFit b = fit_phong_to_reference(r, options);
  EXPECT_EQ(a.lobe.kd, b.lobe.kd);
  EXPECT_EQ(a.lobe.ks, b.lobe.ks);
  EXPECT_EQ(a.lobe.alpha, b.lobe.alpha);
  EXPECT_EQ(a.residual.l2, b.residual.l2);
  // On one thread too: the rows are evaluated independently of how they are split.
  const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  const PhongFit c = fit_phong_to_reference(r, options);
  EXPECT_EQ(a.lobe.kd, c.lobe.kd);
  EXPECT_EQ(a.lobe.ks, c.lobe.ks);
  EXPECT_EQ(a.lobe.alpha, c.lobe.alpha);
}

// Model to model: the best Blinn-Phong lobe for a Phong one is closer than the 4x rule's (kd, ks
// kept, exponent times 4), and its exponent is near 4x for narrow lobes.
TEST(PhongFit, BestBlinnPhongForPhongAgainstTheFourTimesRule) {
  for (double alpha : {10.0, 50.0, 200.0, 1000.0}) {
    PhongLobe phong;
    phong.kd = glm::dvec3(0.2);
    phong.ks = glm::dvec3(0.8);
    phong.alpha = alpha;
    FitOptions options;
    options.model = ShadingModel::blinn_phong;
    const PhongFit best = fit_phong_to_phong(phong, options);
    PhongLobe rule = phong;
    rule.model = ShadingModel::blinn_phong;
    rule.alpha = 4.0 * alpha;
    LobeGrid grid;
    grid.width = lobe_width_for_exponent(4.0 * alpha);
    const LobeSamples samples = make_lobe_samples(grid);
    const LobeResidual by_rule =
        lobe_residual(samples, sample_phong(phong, samples), sample_phong(rule, samples));
    std::printf(
        "Phong alpha %g: best Blinn-Phong alpha %.2f (x%.3f), kd %.3f ks %.3f, l2 rel "
        "%.4f; 4x rule l2 rel %.4f\n",
        alpha, best.lobe.alpha, best.lobe.alpha / alpha, best.lobe.kd.x, best.lobe.ks.x,
        best.residual.l2_relative, by_rule.l2_relative);
    EXPECT_LE(best.residual.l2, by_rule.l2);
  }
}

}  // namespace
}  // namespace gloss

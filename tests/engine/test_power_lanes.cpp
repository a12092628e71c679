// The vectorized c^alpha against the scalar contract of shading.h.
#include "engine/shade/power_lanes.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "shading/shading.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

Scene scene_with_shininess(float alpha) {
  Scene scene;
  test::add_material(
      scene, "m",
      test::make_material(glm::vec3(0), glm::vec3(0), glm::vec3(1), glm::vec3(0), alpha));
  return scene;
}

// Edge lanes of the contract: c <= 0, NaN, c >= 1 (rounding), and ordinary cosines.
const float kCosines[16] = {-0.5f, 0.0f,       std::numeric_limits<float>::quiet_NaN(),
                            1.0f,  1.0000001f, 0.999999f,
                            0.99f, 0.9f,       0.8f,
                            0.5f,  0.25f,      0.1f,
                            1e-3f, 1e-20f,     0.95f,
                            0.7f};

TEST(PowerLanes, ExactModeMatchesSpecularPowerToFloatRounding) {
  for (float alpha : {0.0f, 1.0f, 10.0f, 32.0f, 1000.0f, 1e6f}) {
    const Scene scene = scene_with_shininess(alpha);
    const MaterialExponents e = material_exponents(scene);
    const std::int32_t material[16] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    float out[16];
    specular_power_lanes(e, material, kCosines, out, 16, PowMode::exact);
    for (int i = 0; i < 16; ++i) {
      const float want = specular_power(kCosines[i], alpha);
      // Results under 2^-120 count as zero (power_lanes.h); otherwise a few float ulps.
      if (want < std::ldexp(1.0f, -120)) {
        EXPECT_EQ(out[i], 0.0f) << "alpha " << alpha << " lane " << i;
      } else {
        EXPECT_NEAR(out[i], want, 4e-7f * want) << "alpha " << alpha << " lane " << i;
      }
    }
  }
}

TEST(PowerLanes, HandValuesAndFixedLanes) {
  const Scene scene = scene_with_shininess(10.0f);
  const MaterialExponents e = material_exponents(scene);
  const std::int32_t material[4] = {0, 0, 0, -1};
  const float c[4] = {0.8f, 1.0f, -0.2f, 0.8f};
  float out[4];
  specular_power_lanes(e, material, c, out, 4, PowMode::exact);
  EXPECT_NEAR(out[0], 0.1073741824f, 1e-7f);  // 0.8^10
  EXPECT_EQ(out[1], 1.0f);
  EXPECT_EQ(out[2], 0.0f);
  EXPECT_EQ(out[3], 0.0f);  // no material: a missed lane
}

// A shininess map's lanes with energy normalisation: c^(alpha s) times the normalisation of
// alpha s over the material's alpha (recombination applies the material's), in both pow modes,
// also on the lanes whose power is fixed (s = 0: c^0 = 1; c = 1: 1^alpha = 1). Material alpha
// 10: Phong's normalisation is (alpha + 2) / (2 pi), Blinn-Phong's (alpha + 8) / (8 pi).
TEST(PowerLanes, ShininessMapLanesCarryTheirOwnEnergyNormalisation) {
  const Scene scene = scene_with_shininess(10.0f);
  const MaterialExponents e = material_exponents(scene);
  const std::int32_t material[3] = {0, 0, 0};
  const float c[3] = {0.5f, 1.0f, 0.5f};
  for (ShadingModel model : {ShadingModel::phong, ShadingModel::blinn_phong}) {
    const float k = model == ShadingModel::phong ? 2.0f : 8.0f;
    // alpha 0: 0.5^0 = 1; alpha 10 at c = 1: 1; alpha 2: 0.5^2 = 0.25.
    const float scale[3] = {0.0f, 1.0f, 0.2f};
    ScaledExponent scaled;
    scale_exponents(e, material, scale, 3, true, model, scaled);
    for (PowMode mode : {PowMode::exact, PowMode::fast}) {
      float out[3];
      scaled_power_lanes(e, material, c, out, 3, mode, scaled);
      EXPECT_NEAR(out[0], k / (10.0f + k), 1e-6f) << "mode " << static_cast<int>(mode);
      EXPECT_NEAR(out[1], 1.0f, 1e-6f) << "mode " << static_cast<int>(mode);
      EXPECT_NEAR(out[2], 0.25f * (2.0f + k) / (10.0f + k), 2e-3f)
          << "mode " << static_cast<int>(mode);
    }
  }
}

TEST(PowerLanes, FloorIsWhereThePowerFallsUnderTwoToTheMinus120) {
  const Scene scene = scene_with_shininess(1e6f);
  const MaterialExponents e = material_exponents(scene);
  // 2^(-120 / 1e6) = exp(-8.3178e-5) = 0.99991683
  EXPECT_NEAR(e.floor[0], 0.99991683, 1e-7);
}

TEST(PowerLanes, FastModeMatchesFastSpecularPowerAboveTheFloor) {
  const Scene scene = scene_with_shininess(32.0f);
  const MaterialExponents e = material_exponents(scene);
  const std::int32_t material[16] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  float out[16];
  specular_power_lanes(e, material, kCosines, out, 16, PowMode::fast);
  for (int i = 0; i < 16; ++i) {
    const float want = kCosines[i] >= e.floor[0] ? fast_specular_power(kCosines[i], 32.0f) : 0.0f;
    // The same polynomial; vector and scalar code may contract to FMA differently (an ulp).
    EXPECT_NEAR(out[i], want, 1e-6f * want) << "lane " << i;
  }
}

}  // namespace
}  // namespace gloss

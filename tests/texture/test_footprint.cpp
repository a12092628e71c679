// The ray-cone footprint (texture/footprint.h) and the sphere's (u, v), against hand values.
#include <gtest/gtest.h>

#include <cmath>

#include "texture/footprint.h"
#include "texture/sphere_mapping.h"

namespace gloss {
namespace {

// fov_y 90 degrees, 500 rows: tan(45) = 1, so a pixel spans 2 / 500 = 0.004 at unit distance; at
// 4 spp each sample's cone is half that.
TEST(Footprint, ConeSpreadIsAPixelOverTheSampleCount) {
  EXPECT_NEAR(cone_spread(90.0, 500, 1), 0.004, 1e-15);
  EXPECT_NEAR(cone_spread(90.0, 500, 4), 0.002, 1e-15);
}

// A wall 10 units away seen head-on through that camera: the cone is 0.04 wide there. The wall
// is 8 units wide with u running 0..1 across it and v 0..1 over 8 units: rho = sqrt(1 / 64) =
// 1/8, so the footprint is 0.005 in (u, v). A 1024 x 1024 map: 5.12 texels, level log2(5.12).
TEST(Footprint, LevelOfAWallHeadOn) {
  const double rho =
      triangle_uv_density(glm::dvec3(0, 0, 0), glm::dvec3(8, 0, 0), glm::dvec3(0, 8, 0),
                          glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(0, 1));
  EXPECT_NEAR(rho, 0.125, 1e-15);
  const double f = footprint_uv(10.0, cone_spread(90.0, 500, 1), 1.0, rho);
  EXPECT_NEAR(f, 0.005, 1e-15);
  const double level = footprint_level(f, texel_density_log2(1024, 1024, 1.0, 1.0));
  EXPECT_NEAR(level, std::log2(5.12), 1e-12);
  // Scaled (u, v) twice as fine: one level more. Seen at 60 degrees: cos 0.5, one level more.
  EXPECT_NEAR(footprint_level(f, texel_density_log2(1024, 1024, 2.0, 2.0)), level + 1.0, 1e-12);
  EXPECT_NEAR(footprint_level(footprint_uv(10.0, cone_spread(90.0, 500, 1), 0.5, rho),
                              texel_density_log2(1024, 1024, 1.0, 1.0)),
              level + 1.0, 1e-12);
}

TEST(Footprint, DegenerateCoordinatesReadLevelZero) {
  const double rho =
      triangle_uv_density(glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0),
                          glm::dvec2(0.3, 0.3), glm::dvec2(0.3, 0.3), glm::dvec2(0.3, 0.3));
  EXPECT_EQ(rho, 0.0);
  EXPECT_TRUE(std::isinf(footprint_level(footprint_uv(5.0, 0.01, 1.0, rho), 10.0)));
}

TEST(SphereMapping, FrontIsTheMapsMiddleAndUGrowsTowardsPlusX) {
  EXPECT_EQ(sphere_uv(glm::dvec3(0, 0, 1)), glm::dvec2(0.5, 0.5));
  EXPECT_NEAR(sphere_uv(glm::dvec3(1, 0, 0)).x, 0.75, 1e-15);
  EXPECT_NEAR(sphere_uv(glm::dvec3(-1, 0, 0)).x, 0.25, 1e-15);
  EXPECT_NEAR(sphere_uv(glm::dvec3(0, 1, 0)).y, 1.0, 1e-15);
  EXPECT_NEAR(sphere_uv(glm::dvec3(0, -1, 0)).y, 0.0, 1e-15);
  // The tangent at the front is +x; cross(N, T) = cross(+z, +x) = +y, up the meridian.
  EXPECT_EQ(sphere_tangent(glm::dvec3(0, 0, 1)), glm::dvec3(1, 0, 0));
  EXPECT_EQ(sphere_tangent(glm::dvec3(0, 1, 0)), glm::dvec3(1, 0, 0));  // the pole's choice
}

// dA_uv / dA_world = 1 / (2 pi^2 r^2 cos beta): at the equator of a unit sphere rho^2 = 1/(2 pi^2).
TEST(SphereMapping, DensityAtTheEquator) {
  EXPECT_NEAR(sphere_uv_density(1.0, 0.0), 1.0 / std::sqrt(2.0 * M_PI * M_PI), 1e-15);
  EXPECT_NEAR(sphere_uv_density(2.0, 0.0), 0.5 / std::sqrt(2.0 * M_PI * M_PI), 1e-15);
}

}  // namespace
}  // namespace gloss

// The UV checker (texture/uv_checker.h): texels worked out by hand from its rules, and a lookup
// at a (u, v) reading the cell of that (u, v), so the hue runs with u and the brightness with v.
#include <gtest/gtest.h>

#include "texture/texture_lookup.h"
#include "texture/uv_checker.h"

namespace gloss {
namespace {

void expect_colour(const glm::vec3& c, float r, float g, float b) {
  EXPECT_NEAR(c.r, r, 1e-6f);
  EXPECT_NEAR(c.g, g, 1e-6f);
  EXPECT_NEAR(c.b, b, 1e-6f);
}

TEST(UvChecker, TexelsFollowTheRules) {
  // 512 x 512: cells of 64 texels, the marker 16 x 16 at the bottom left (rows 496..511).
  expect_colour(uv_checker_texel(3, 508, 512), 1, 1, 1);  // the (0, 0) marker
  // Texel (100, 411): 100 texels from the left and from the bottom: cell (1, 1), i + j even.
  // Hue 1/8 (45 degrees) at value 0.2 + 0.8 / 7 = 0.3142857: (value, 0.75 value, 0).
  expect_colour(uv_checker_texel(100, 411, 512), 0.3142857f, 0.2357143f, 0.0f);
  // Texel (100, 481): cell (1, 0), odd: the hue's (0.2, 0.15, 0) times 0.4 plus 0.6 * 0.2.
  expect_colour(uv_checker_texel(100, 481, 512), 0.2f, 0.18f, 0.12f);
  // Cell (7, 7) at the top right: hue 7/8 (315 degrees), value 1: (1, 0, 0.75).
  expect_colour(uv_checker_texel(500, 11, 512), 1.0f, 0.0f, 0.75f);
  // The grid: the first and last texel column of a cell.
  expect_colour(uv_checker_texel(64, 300, 512), 0.02f, 0.02f, 0.02f);
  expect_colour(uv_checker_texel(127, 300, 512), 0.02f, 0.02f, 0.02f);
}

TEST(UvChecker, ALookupReadsTheCellOfItsCoordinates) {
  const Texture t = make_uv_checker(512);
  ASSERT_EQ(t.channels, 4);
  ASSERT_EQ(t.width(), 512);
  EXPECT_EQ(t.level_count(), 10);  // 512 down to 1
  // The middle of cell (1, 1), u = v = 1.5 / 8: texels 95/96 and rows 415/416, all inside it.
  const glm::dvec4 c = bilinear<double>(t, 0, 0.1875, 0.1875, Wrap::repeat, Wrap::repeat);
  EXPECT_NEAR(c.r, 0.3142857, 1e-6);
  EXPECT_NEAR(c.g, 0.2357143, 1e-6);
  EXPECT_NEAR(c.b, 0.0, 1e-6);
  EXPECT_NEAR(c.a, 1.0, 1e-6);
  // Cell (6, 2) (u = 6.5 / 8, v = 2.5 / 8): even, hue 6/8 = 270 degrees, value 0.2 + 1.6 / 7:
  // sector 4 at f = 0.5, (0.5 value, 0, value).
  const glm::dvec4 d = bilinear<double>(t, 0, 0.8125, 0.3125, Wrap::repeat, Wrap::repeat);
  const double value = 0.2 + 1.6 / 7.0;
  EXPECT_NEAR(d.r, 0.5 * value, 1e-6);
  EXPECT_NEAR(d.g, 0.0, 1e-6);
  EXPECT_NEAR(d.b, value, 1e-6);
  // The shared one is made once.
  EXPECT_EQ(shared_uv_checker().get(), shared_uv_checker().get());
}

}  // namespace
}  // namespace gloss

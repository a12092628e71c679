// Texture lookups against values worked out by hand from docs/spec/shading.md, "Textures":
// texel (i, j) has its centre at u = (i + 0.5) / W, v = 1 - (j + 0.5) / H; bilinear weights
// between the four nearest centres; the wrap modes; trilinear between two levels.
#include <gtest/gtest.h>

#include "texture/mip_pyramid.h"
#include "texture/texture_lookup.h"

namespace gloss {
namespace {

// A grey texture of w x h with the given texels, row 0 at the top.
Texture grey(int w, int h, std::vector<float> values) {
  FloatImage image;
  image.width = w;
  image.height = h;
  image.channels = 1;
  image.samples = std::move(values);
  return make_texture(std::move(image));
}

float at(const Texture& t, float u, float v, Wrap wu = Wrap::repeat, Wrap wv = Wrap::repeat) {
  return bilinear(t, 0, u, v, wu, wv).x;
}

// 2 x 2:  top row 10 20, bottom row 30 40.
TEST(TextureLookup, TexelCentresGiveTheirTexel) {
  const Texture t = grey(2, 2, {10, 20, 30, 40});
  EXPECT_FLOAT_EQ(at(t, 0.25f, 0.75f), 10.0f);  // i 0, j 0: u = 0.25, v = 1 - 0.25
  EXPECT_FLOAT_EQ(at(t, 0.75f, 0.75f), 20.0f);
  EXPECT_FLOAT_EQ(at(t, 0.25f, 0.25f), 30.0f);  // j 1 is the bottom row: v = 0.25
  EXPECT_FLOAT_EQ(at(t, 0.75f, 0.25f), 40.0f);
}

TEST(TextureLookup, HalfwayBetweenCentresIsTheMean) {
  const Texture t = grey(2, 2, {10, 20, 30, 40});
  EXPECT_FLOAT_EQ(at(t, 0.5f, 0.75f), 15.0f);  // between 10 and 20
  EXPECT_FLOAT_EQ(at(t, 0.25f, 0.5f), 20.0f);  // between 10 (top) and 30 (bottom)
  EXPECT_FLOAT_EQ(at(t, 0.5f, 0.5f), 25.0f);   // all four
}

// Magnified: a quarter of the way from centre (0, 0) to (1, 0) and from row 0 to row 1:
// x = 0.25 W... worked out: u = 0.375 -> x = 0.375 * 2 - 0.5 = 0.25; v = 0.625 -> y = 0.25.
// (1 - 0.25)(1 - 0.25) 10 + 0.25 (0.75) 20 + 0.75 (0.25) 30 + 0.25 (0.25) 40 = 17.5.
TEST(TextureLookup, MagnifiedMapsAreBilinearByHand) {
  const Texture t = grey(2, 2, {10, 20, 30, 40});
  EXPECT_FLOAT_EQ(at(t, 0.375f, 0.625f), 17.5f);
}

// A 4 x 1 strip 0 1 2 3 (centres at u = 0.125 ... 0.875); v is the middle row everywhere.
TEST(TextureLookup, RepeatWrapsAroundTheEdge) {
  const Texture t = grey(4, 1, {0, 1, 2, 3});
  EXPECT_FLOAT_EQ(at(t, 0.0f, 0.5f), 1.5f);           // between texel 3 (wrapped) and texel 0
  EXPECT_FLOAT_EQ(at(t, 1.125f, 0.5f), 0.0f);         // one period on: texel 0's centre
  EXPECT_FLOAT_EQ(at(t, -0.875f, 0.5f), 0.0f);        // one period back
  EXPECT_FLOAT_EQ(at(t, 1e6f + 0.375f, 0.5f), 1.0f);  // far away: 1e6 + 0.375 is exact in float
}

TEST(TextureLookup, ClampHoldsTheEdgeTexel) {
  const Texture t = grey(4, 1, {0, 1, 2, 3});
  EXPECT_FLOAT_EQ(at(t, 0.0f, 0.5f, Wrap::clamp), 0.0f);
  EXPECT_FLOAT_EQ(at(t, -5.0f, 0.5f, Wrap::clamp), 0.0f);
  EXPECT_FLOAT_EQ(at(t, 1.0f, 0.5f, Wrap::clamp), 3.0f);
  EXPECT_FLOAT_EQ(at(t, 0.9375f, 0.5f, Wrap::clamp), 3.0f);  // past the last centre
}

// Mirror: u in (1, 2) reads the strip backwards; 1.125 is texel 3's mirror image.
TEST(TextureLookup, MirrorRunsBackAndForth) {
  const Texture t = grey(4, 1, {0, 1, 2, 3});
  EXPECT_FLOAT_EQ(at(t, 1.0f, 0.5f, Wrap::mirror), 3.0f);  // the edge between 3 and its image
  EXPECT_FLOAT_EQ(at(t, 1.125f, 0.5f, Wrap::mirror), 3.0f);
  EXPECT_FLOAT_EQ(at(t, 1.375f, 0.5f, Wrap::mirror), 2.0f);
  EXPECT_FLOAT_EQ(at(t, -0.125f, 0.5f, Wrap::mirror), 0.0f);  // texel 0's image below 0
  EXPECT_FLOAT_EQ(at(t, 2.125f, 0.5f, Wrap::mirror), 0.0f);   // a whole period (2) on
}

TEST(TextureLookup, WrapIsPerAxis) {
  // 1 x 4 column, top to bottom 0 1 2 3: clamp in v, repeat in u.
  const Texture t = grey(1, 4, {0, 1, 2, 3});
  EXPECT_FLOAT_EQ(at(t, 7.3f, 1.5f, Wrap::repeat, Wrap::clamp), 0.0f);   // above the top: row 0
  EXPECT_FLOAT_EQ(at(t, 0.5f, -1.0f, Wrap::repeat, Wrap::clamp), 3.0f);  // below: the last row
}

TEST(TextureLookup, NearestTakesTheTexelUnderThePoint) {
  const Texture t = grey(4, 1, {0, 1, 2, 3});
  EXPECT_FLOAT_EQ(nearest(t, 0, 0.24f, 0.5f, Wrap::repeat, Wrap::repeat).x, 0.0f);
  EXPECT_FLOAT_EQ(nearest(t, 0, 0.26f, 0.5f, Wrap::repeat, Wrap::repeat).x, 1.0f);
  EXPECT_FLOAT_EQ(nearest(t, 0, 0.99f, 0.5f, Wrap::repeat, Wrap::repeat).x, 3.0f);
}

// Level 1 of the 2 x 2 map is the mean 25; level 0.25 is 3/4 of level 0 and 1/4 of level 1.
TEST(TextureLookup, TrilinearBlendsTheTwoLevels) {
  const Texture t = grey(2, 2, {10, 20, 30, 40});
  ASSERT_EQ(t.level_count(), 2);
  EXPECT_FLOAT_EQ(trilinear(t, 0.0f, 0.25f, 0.75f, Wrap::repeat, Wrap::repeat).x, 10.0f);
  EXPECT_FLOAT_EQ(trilinear(t, 0.25f, 0.25f, 0.75f, Wrap::repeat, Wrap::repeat).x,
                  0.75f * 10.0f + 0.25f * 25.0f);
  EXPECT_FLOAT_EQ(trilinear(t, 1.0f, 0.25f, 0.75f, Wrap::repeat, Wrap::repeat).x, 25.0f);
  EXPECT_FLOAT_EQ(trilinear(t, 9.0f, 0.25f, 0.75f, Wrap::repeat, Wrap::repeat).x, 25.0f);
  EXPECT_FLOAT_EQ(trilinear(t, -3.0f, 0.25f, 0.75f, Wrap::repeat, Wrap::repeat).x, 10.0f);
}

TEST(TextureLookup, OneTexelMapsAreConstant) {
  const Texture t = grey(1, 1, {0.25f});
  for (float u : {-1e6f, -0.3f, 0.0f, 0.5f, 1.0f, 7.7f, 1e6f}) {
    EXPECT_FLOAT_EQ(at(t, u, u * 0.5f), 0.25f);
    EXPECT_FLOAT_EQ(at(t, u, u, Wrap::mirror, Wrap::clamp), 0.25f);
  }
}

TEST(TextureLookup, ColourMapsKeepAlphaAndGreyReadsAsRgb) {
  FloatImage image;
  image.width = 1;
  image.height = 1;
  image.channels = 2;  // grey and alpha
  image.samples = {0.5f, 0.25f};
  const Texture t = make_texture(image);
  const glm::vec4 texel = bilinear(t, 0, 0.5f, 0.5f, Wrap::repeat, Wrap::repeat);
  EXPECT_EQ(texel, glm::vec4(0.5f, 0.5f, 0.5f, 0.25f));
  EXPECT_TRUE(t.has_alpha);
}

TEST(TextureLookup, NonFiniteCoordinatesReadTheFirstTexelNotUndefined) {
  const Texture t = grey(2, 1, {3, 5});
  const float nan = std::nanf("");
  EXPECT_TRUE(std::isfinite(at(t, nan, 0.5f)));
  EXPECT_TRUE(std::isfinite(at(t, INFINITY, -INFINITY, Wrap::mirror, Wrap::clamp)));
}

}  // namespace
}  // namespace gloss

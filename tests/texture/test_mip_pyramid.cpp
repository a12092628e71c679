// Mip pyramids: each level the box filter of exactly the area its texels cover
// (texture/mip_pyramid.h), so a level's mean is the image's, checked by hand.
#include <gtest/gtest.h>

#include <numeric>

#include "texture/mip_pyramid.h"

namespace gloss {
namespace {

FloatImage grey(int w, int h, std::vector<float> values) {
  FloatImage image;
  image.width = w;
  image.height = h;
  image.channels = 1;
  image.samples = std::move(values);
  return image;
}

TEST(MipPyramid, EvenSidesAverageTwoByTwo) {
  // 4 x 2:  1 2 3 4 / 5 6 7 8  ->  2 x 1: (1+2+5+6)/4 = 3.5, (3+4+7+8)/4 = 5.5  ->  1 x 1: 4.5
  const Texture t = make_texture(grey(4, 2, {1, 2, 3, 4, 5, 6, 7, 8}));
  ASSERT_EQ(t.level_count(), 3);
  EXPECT_EQ(t.levels[1].width, 2);
  EXPECT_EQ(t.levels[1].height, 1);
  EXPECT_FLOAT_EQ(t.levels[1].texels[0], 3.5f);
  EXPECT_FLOAT_EQ(t.levels[1].texels[1], 5.5f);
  EXPECT_FLOAT_EQ(t.levels[2].texels[0], 4.5f);
}

TEST(MipPyramid, OddSidesGiveEveryTexelItsShare) {
  // A side of 3 becomes 1: weights (1 - 0)/3, 1/3, (0 + 1)/3 = 1/3 each.
  const Texture t = make_texture(grey(3, 1, {3, 6, 9}));
  ASSERT_EQ(t.level_count(), 2);
  EXPECT_FLOAT_EQ(t.levels[1].texels[0], 6.0f);
  // A side of 5 becomes 2: texel 0 takes 2/5, 2/5, 1/5 of texels 0..2; texel 1 1/5, 2/5, 2/5
  // of texels 2..4.
  const Texture f = make_texture(grey(5, 1, {5, 10, 15, 20, 25}));
  EXPECT_FLOAT_EQ(f.levels[1].texels[0], 0.4f * 5 + 0.4f * 10 + 0.2f * 15);
  EXPECT_FLOAT_EQ(f.levels[1].texels[1], 0.2f * 15 + 0.4f * 20 + 0.4f * 25);
}

TEST(MipPyramid, EveryLevelKeepsTheMean) {
  std::vector<float> values(7 * 5);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<float>((i * 37) % 11);
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / values.size();
  const Texture t = make_texture(grey(7, 5, values));
  EXPECT_EQ(t.levels.back().width, 1);
  EXPECT_EQ(t.levels.back().height, 1);
  for (const MipLevel& level : t.levels) {
    const double m =
        std::accumulate(level.texels.begin(), level.texels.end(), 0.0) / level.texels.size();
    // A level's texels cover equal areas, so their plain mean is the area mean.
    EXPECT_NEAR(m, mean, 1e-5) << level.width << "x" << level.height;
  }
}

TEST(MipPyramid, BudgetEstimateCoversThePyramid) {
  for (int w : {1, 2, 3, 17, 256}) {
    for (int h : {1, 5, 64}) {
      FloatImage image = grey(w, h, std::vector<float>(static_cast<std::size_t>(w) * h, 1.0f));
      image.channels = 1;
      const Texture t = make_texture(image);
      EXPECT_LE(t.bytes(), pyramid_bytes(w, h, 1)) << w << "x" << h;
    }
  }
}

TEST(MipPyramid, RgbGetsAlphaOne) {
  FloatImage image;
  image.width = 1;
  image.height = 1;
  image.channels = 3;
  image.samples = {0.1f, 0.2f, 0.3f};
  const Texture t = make_texture(image);
  EXPECT_EQ(t.channels, 4);
  EXPECT_FALSE(t.has_alpha);
  EXPECT_EQ(t.levels[0].texels, (std::vector<float>{0.1f, 0.2f, 0.3f, 1.0f}));
}

}  // namespace
}  // namespace gloss

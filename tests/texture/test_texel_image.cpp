// texel_image lays texel(i, j) out row by row from the top, keeping the first `channels`
// components: the values below are written out by hand from that layout.
#include "texture/texel_image.h"

#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <gtest/gtest.h>

namespace gloss {
namespace {

TEST(TexelImage, RowsFromTheTopEachTexelsFirstChannels) {
  // 3 x 2 texels, 2 channels: texel (i, j) = (10 j + i, 100 + 10 j + i, dropped, dropped).
  const FloatImage image = texel_image(3, 2, 2, [](int i, int j) {
    return glm::vec4(10.0f * j + i, 100.0f + 10.0f * j + i, -1.0f, -1.0f);
  });
  EXPECT_EQ(image.width, 3);
  EXPECT_EQ(image.height, 2);
  EXPECT_EQ(image.channels, 2);
  const std::vector<float> expected = {0, 100, 1, 101, 2, 102, 10, 110, 11, 111, 12, 112};
  EXPECT_EQ(image.samples, expected);
}

TEST(TexelImage, ThreeChannelsFromAVec3) {
  const FloatImage image =
      texel_image(1, 2, 3, [](int, int j) { return glm::vec3(j, 0.5f, 0.25f); });
  const std::vector<float> expected = {0, 0.5f, 0.25f, 1, 0.5f, 0.25f};
  EXPECT_EQ(image.samples, expected);
}

}  // namespace
}  // namespace gloss

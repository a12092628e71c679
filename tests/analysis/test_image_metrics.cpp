// Error figures of gloss-cli tradeoff (image_metrics.h) and the preview upsampling
// (image_resample.h) on small hand-made images, with the expected numbers worked out by hand.
#include "analysis/image/image_metrics.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "analysis/image/image_resample.h"

namespace gloss {
namespace {

TEST(ImageMetrics, IdenticalImagesHaveZeroErrorAndInfinitePsnr) {
  const Image a(3, 2, glm::vec3(0.25f, 0.5f, 2.0f));
  const ImageMetrics m = compare_images(a, a);
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_EQ(m.max_abs, 0.0);
  EXPECT_EQ(m.pct_pixels_off, 0.0);
  EXPECT_TRUE(std::isinf(m.psnr_db) && m.psnr_db > 0);
  EXPECT_EQ(m.pixels, 6u);
}

// 2 x 2 pixels, 12 channel values; one channel off by 0.5:
// mse = 0.25 / 12, rmse = 0.5 / sqrt(12) = 0.1443375673, psnr = 10 log10(48) = 16.8124123738.
TEST(ImageMetrics, OneChannelOffGivesHandComputedFigures) {
  const Image ref(2, 2, glm::vec3(0.5f));
  Image test = ref;
  test.at(1, 0).y = 1.0f;
  const ImageMetrics m = compare_images(test, ref);
  EXPECT_NEAR(m.rmse, 0.1443375673, 1e-9);
  EXPECT_NEAR(m.psnr_db, 16.8124123738, 1e-8);
  EXPECT_DOUBLE_EQ(m.max_abs, 0.5);
  EXPECT_DOUBLE_EQ(m.pct_pixels_off, 25.0);
}

// Linear values, unclamped: 3.0 against 1.0 is off by 2 (a display would show both as white).
TEST(ImageMetrics, ValuesAboveOneAreComparedUnclamped) {
  const Image ref(1, 1, glm::vec3(1.0f));
  const Image test(1, 1, glm::vec3(3.0f, 1.0f, 1.0f));
  const ImageMetrics m = compare_images(test, ref);
  EXPECT_DOUBLE_EQ(m.max_abs, 2.0);
  EXPECT_NEAR(m.rmse, std::sqrt(4.0 / 3.0), 1e-12);
}

// "Off" means more than one 8-bit step, 1/255 = 0.00392: 0.003 is not off, 0.005 is.
TEST(ImageMetrics, PixelsOffCountsOnlyDifferencesAboveOneDisplayStep) {
  const Image ref(4, 1, glm::vec3(0.5f));
  Image test = ref;
  test.at(0, 0).x += 0.003f;
  test.at(1, 0).z -= 0.005f;
  test.at(2, 0) += glm::vec3(0.003f);
  const ImageMetrics m = compare_images(test, ref);
  EXPECT_DOUBLE_EQ(m.pct_pixels_off, 25.0);
}

TEST(ImageMetrics, NonFiniteValuesCountAsInfinitelyFarAndOff) {
  const Image ref(2, 1, glm::vec3(0.5f));
  Image test = ref;
  test.at(0, 0).x = std::numeric_limits<float>::quiet_NaN();
  const ImageMetrics m = compare_images(test, ref);
  EXPECT_TRUE(std::isinf(m.rmse));
  EXPECT_TRUE(std::isinf(m.max_abs));
  EXPECT_TRUE(std::isinf(m.psnr_db) && m.psnr_db < 0);
  EXPECT_DOUBLE_EQ(m.pct_pixels_off, 50.0);
}

// The mask splits the image: the edge pixel carries the whole error, the interior none.
TEST(ImageMetrics, MaskSelectsInteriorAndEdgePixels) {
  const Image ref(3, 1, glm::vec3(0.0f));
  Image test = ref;
  test.at(2, 0) = glm::vec3(0.3f);
  const std::vector<std::uint8_t> edges{0, 0, 1};
  const ImageMetrics interior = compare_images(test, ref, edges, 0);
  const ImageMetrics edge = compare_images(test, ref, edges, 1);
  EXPECT_EQ(interior.pixels, 2u);
  EXPECT_EQ(interior.max_abs, 0.0);
  EXPECT_EQ(edge.pixels, 1u);
  EXPECT_NEAR(edge.rmse, 0.3, 1e-7);
  EXPECT_DOUBLE_EQ(edge.pct_pixels_off, 100.0);
  const ImageMetrics none = compare_images(test, ref, edges, 7);
  EXPECT_EQ(none.pixels, 0u);
}

TEST(ImageMetrics, SizeMismatchIsRefused) {
  EXPECT_THROW(compare_images(Image(2, 2), Image(2, 3)), std::invalid_argument);
  EXPECT_THROW(compare_images(Image(2, 2), Image(2, 2), std::vector<std::uint8_t>(3), 0),
               std::invalid_argument);
}

// 2 x 1 -> 4 x 1: target centres 0.5, 1.5, 2.5, 3.5 map to source coordinates
// (x + 0.5) * 2 / 4 - 0.5 = -0.25, 0.25, 0.75, 1.25, clamped to [0, 1]: 0, 0.25, 0.75, 1.
TEST(ImageResample, BilinearUpsamplingInterpolatesBetweenPixelCentres) {
  Image src(2, 1);
  src.at(0, 0) = glm::vec3(0.0f);
  src.at(1, 0) = glm::vec3(1.0f, 2.0f, 4.0f);
  const Image up = resize_bilinear(src, 4, 1);
  const float expected[] = {0.0f, 0.25f, 0.75f, 1.0f};
  for (int x = 0; x < 4; ++x) {
    EXPECT_NEAR(up.at(x, 0).x, expected[x], 1e-6f);
    EXPECT_NEAR(up.at(x, 0).z, 4.0f * expected[x], 1e-6f);
  }
}

TEST(ImageResample, ConstantImagesStayConstantAndEqualSizesCopy) {
  const Image flat(3, 2, glm::vec3(0.2f, 0.4f, 0.6f));
  const Image up = resize_bilinear(flat, 24, 17);
  for (const glm::vec3& p : up.pixels) {
    EXPECT_NEAR(p.y, 0.4f, 1e-6f);
  }
  Image varied(2, 2);
  varied.at(1, 1) = glm::vec3(5.0f);
  EXPECT_EQ(resize_bilinear(varied, 2, 2).pixels, varied.pixels);
}

}  // namespace
}  // namespace gloss

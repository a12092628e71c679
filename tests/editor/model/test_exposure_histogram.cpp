// The viewport's histogram and clipped share on hand-made images. Expected bins are
// floor(displayed * 64) worked out by hand; sRGB values from the standard curve.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "editor/model/measure/exposure_histogram.h"

namespace gloss {
namespace {

// The display transform at stops of exposure, with tone and encoding.
DisplayTransform shown(float stops, bool srgb = false, ToneCurve tone = ToneCurve::none) {
  RenderSettings render;
  render.exposure = stops;
  render.srgb = srgb;
  render.tone = tone;
  return display_transform(render);
}

// black, mid grey, white, and a red above white with dim green and blue.
Image four_pixels() {
  Image image(2, 2);
  image.at(0, 0) = glm::vec3(0.0f);
  image.at(1, 0) = glm::vec3(0.5f);
  image.at(0, 1) = glm::vec3(1.0f);
  image.at(1, 1) = glm::vec3(2.0f, 0.2f, 0.2f);
  return image;
}

TEST(ExposureHistogram, ClippedMeansAnyChannelAboveOneAfterExposure) {
  const ExposureHistogram h = exposure_histogram(four_pixels(), shown(0.0f, false));
  EXPECT_EQ(h.pixels, 4u);
  // Only the red pixel: white at exactly 1 is shown as is, not clipped.
  EXPECT_EQ(h.clipped, 1u);
  EXPECT_DOUBLE_EQ(h.clipped_share(), 0.25);
  EXPECT_EQ(h.clipped_channel[0], 1u);
  EXPECT_EQ(h.clipped_channel[1], 0u);
  EXPECT_EQ(h.clipped_channel[2], 0u);
}

TEST(ExposureHistogram, ExposureMovesTheClipPoint) {
  // +1 stop: 0.5 -> 1.0 (not clipped), 1 -> 2 and 2 -> 4 (clipped).
  EXPECT_DOUBLE_EQ(exposure_histogram(four_pixels(), shown(1.0f, false)).clipped_share(), 0.5);
  // -1 stop: 2 -> 1.0 exactly: nothing clipped.
  EXPECT_DOUBLE_EQ(exposure_histogram(four_pixels(), shown(-1.0f, false)).clipped_share(), 0.0);
  // +3 stops: 0.5 -> 4 too; black stays black.
  EXPECT_DOUBLE_EQ(exposure_histogram(four_pixels(), shown(3.0f, false)).clipped_share(), 0.75);
}

TEST(ExposureHistogram, ClassicClampBinsTheClampedValue) {
  const ExposureHistogram h = exposure_histogram(four_pixels(), shown(0.0f, false));
  // Red: 0 -> bin 0, 0.5 -> bin 32, 1 and 2 (clamped to 1) -> bin 63.
  EXPECT_EQ(h.counts[0][0], 1u);
  EXPECT_EQ(h.counts[0][32], 1u);
  EXPECT_EQ(h.counts[0][63], 2u);
  // Green: 0, 0.5, 1, and 0.2 -> floor(12.8) = bin 12.
  EXPECT_EQ(h.counts[1][0], 1u);
  EXPECT_EQ(h.counts[1][12], 1u);
  EXPECT_EQ(h.counts[1][32], 1u);
  EXPECT_EQ(h.counts[1][63], 1u);
  std::uint64_t total = 0;
  for (std::uint32_t n : h.counts[2]) total += n;
  EXPECT_EQ(total, 4u);
}

TEST(ExposureHistogram, SrgbBinsTheEncodedValue) {
  // Linear 0.05: classic 0.05 * 64 = 3.2 -> bin 3; sRGB 1.055 * 0.05^(1/2.4) - 0.055 = 0.2478,
  // x 64 = 15.86 -> bin 15.
  const Image image(1, 1, glm::vec3(0.05f));
  EXPECT_EQ(exposure_histogram(image, shown(0.0f, false)).counts[0][3], 1u);
  EXPECT_EQ(exposure_histogram(image, shown(0.0f, true)).counts[0][15], 1u);
}

TEST(ExposureHistogram, NanAndNegativeShowAsBlack) {
  Image image(2, 1);
  image.at(0, 0) = glm::vec3(std::numeric_limits<float>::quiet_NaN());
  image.at(1, 0) = glm::vec3(-1.0f);
  const ExposureHistogram h = exposure_histogram(image, shown(0.0f, true));
  EXPECT_EQ(h.counts[0][0], 2u);
  EXPECT_EQ(h.clipped, 0u);
}

TEST(ExposureHistogram, StepBinsEveryStepthPixelButCountsEveryClippedOne) {
  // 4 x 4, clipped only in column 1: step 2 bins columns 0 and 2 of rows 0 and 2, and still
  // counts the clipped column the overlay stripes (the panel once said 0.0% beside it).
  Image image(4, 4, glm::vec3(0.25f));
  for (int y = 0; y < 4; ++y) image.at(1, y) = glm::vec3(5.0f);
  EXPECT_DOUBLE_EQ(exposure_histogram(image, shown(0.0f, false)).clipped_share(), 0.25);
  const ExposureHistogram sparse = exposure_histogram(image, shown(0.0f, false), 2);
  EXPECT_EQ(sparse.pixels, 4u);
  EXPECT_EQ(sparse.clipped, 4u);
  EXPECT_DOUBLE_EQ(sparse.clipped_share(), 0.25);
  EXPECT_DOUBLE_EQ(sparse.clipped_channel_share(2), 0.25);
}

TEST(ExposureHistogram, ToneCurvesMoveTheClipPoint) {
  Image image(3, 1);
  image.at(0, 0) = glm::vec3(2.0f);
  image.at(1, 0) = glm::vec3(7.0f);
  image.at(2, 0) = glm::vec3(8.0f);
  // No curve: 2, 7 and 8 are above 1. Reinhard never reaches 1. ACES crosses 1 at 7.2417.
  EXPECT_EQ(exposure_histogram(image, shown(0.0f)).clipped, 3u);
  EXPECT_EQ(exposure_histogram(image, shown(0.0f, false, ToneCurve::reinhard)).clipped, 0u);
  EXPECT_EQ(exposure_histogram(image, shown(0.0f, false, ToneCurve::aces)).clipped, 1u);
  // One stop up under ACES: 7 and 8 become 14 and 16 and clip, 2 becomes 4 and does not.
  EXPECT_EQ(exposure_histogram(image, shown(1.0f, false, ToneCurve::aces)).clipped, 2u);
  // Reinhard of 2: 2/3 -> bin floor(42.67) = 42.
  EXPECT_EQ(exposure_histogram(image, shown(0.0f, false, ToneCurve::reinhard)).counts[0][42], 1u);
}

TEST(ExposureHistogram, ClippedTextShowsSmallSharesAsSuch) {
  EXPECT_EQ(clipped_text(0.0), "0%");
  EXPECT_EQ(clipped_text(1.0 / 100000), "< 0.1%");
  EXPECT_EQ(clipped_text(0.0004), "< 0.1%");
  EXPECT_EQ(clipped_text(0.0006), "0.1%");
  EXPECT_EQ(clipped_text(0.125), "12.5%");
}

TEST(ExposureHistogram, EmptyImageHasNoShare) {
  EXPECT_EQ(exposure_histogram(Image(), shown(0.0f, false)).clipped_share(), 0.0);
}

}  // namespace
}  // namespace gloss

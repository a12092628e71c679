// The display transform (docs/spec/shading.md, "Output encodings") at values worked out by hand:
// the tone curves, the order exposure -> tone -> clamp -> encoding, the 8-bit rounding, and the
// batch loops against the scalar functions.
#include "display/display_transform.h"

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

namespace gloss {
namespace {

DisplayTransform transform(float stops, ToneCurve tone, bool srgb = false) {
  RenderSettings render;
  render.exposure = stops;
  render.tone = tone;
  render.srgb = srgb;
  return display_transform(render);
}

TEST(DisplayTransform, ExposureIsTwoToTheStops) {
  EXPECT_FLOAT_EQ(transform(3.0f, ToneCurve::none).gain, 8.0f);
  EXPECT_FLOAT_EQ(transform(-2.0f, ToneCurve::none).gain, 0.25f);
  EXPECT_FLOAT_EQ(display_value(0.8f, transform(-2.0f, ToneCurve::none)), 0.2f);
  EXPECT_FLOAT_EQ(display_value(0.3f, transform(1.0f, ToneCurve::none)), 0.6f);
}

TEST(DisplayTransform, NoneIsTheClassicClamp) {
  const DisplayTransform none = transform(0.0f, ToneCurve::none);
  EXPECT_FLOAT_EQ(display_value(0.5f, none), 0.5f);
  EXPECT_FLOAT_EQ(display_value(2.0f, none), 1.0f);
  EXPECT_FLOAT_EQ(display_toned(2.0f, none), 2.0f);  // what the clamp clips
  EXPECT_EQ(display_value(-1.0f, none), 0.0f);
  EXPECT_EQ(display_value(std::numeric_limits<float>::quiet_NaN(), none), 0.0f);
  EXPECT_EQ(display_value(std::numeric_limits<float>::infinity(), none), 1.0f);
}

TEST(DisplayTransform, ReinhardCurve) {
  // x / (1 + x): 1 -> 1/2, 3 -> 3/4, 0.25 -> 1/5; never reaches 1, so nothing clips.
  EXPECT_FLOAT_EQ(tone_curve(1.0f, ToneCurve::reinhard), 0.5f);
  EXPECT_FLOAT_EQ(tone_curve(3.0f, ToneCurve::reinhard), 0.75f);
  EXPECT_FLOAT_EQ(tone_curve(0.25f, ToneCurve::reinhard), 0.2f);
  const DisplayTransform reinhard = transform(0.0f, ToneCurve::reinhard);
  EXPECT_LT(display_toned(1000.0f, reinhard), 1.0f);
  EXPECT_EQ(display_value(std::numeric_limits<float>::infinity(), reinhard), 1.0f);
  EXPECT_EQ(display_value(-0.5f, reinhard), 0.0f);  // not the curve's -1: negatives show as 0
}

TEST(DisplayTransform, AcesFitCurve) {
  // x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14):
  //   x = 1:    2.54 / 3.16 = 0.8037975
  //   x = 0.18: 0.18 x 0.4818 / (0.18 x 1.0274 + 0.14) = 0.086724 / 0.324932 = 0.2668989
  //   x = 100:  25103 / 24359.14 = 1.0305373, above 1: clipped, displayed as 1.
  EXPECT_NEAR(tone_curve(1.0f, ToneCurve::aces), 0.8037975, 1e-6);
  EXPECT_NEAR(tone_curve(0.18f, ToneCurve::aces), 0.2668989, 1e-6);
  EXPECT_NEAR(tone_curve(100.0f, ToneCurve::aces), 1.0305373, 1e-6);
  EXPECT_EQ(tone_curve(0.0f, ToneCurve::aces), 0.0f);
  const DisplayTransform aces = transform(0.0f, ToneCurve::aces);
  EXPECT_EQ(display_value(100.0f, aces), 1.0f);
  // It crosses 1 where 0.08 x^2 - 0.56 x - 0.14 = 0: x = (0.56 + sqrt(0.3584)) / 0.16 = 7.2417.
  EXPECT_LT(display_toned(7.2f, aces), 1.0f);
  EXPECT_GT(display_toned(7.3f, aces), 1.0f);
  EXPECT_EQ(display_value(std::numeric_limits<float>::infinity(), aces), 1.0f);
}

TEST(DisplayTransform, ExposureComesBeforeTheCurve) {
  // 0.5 at +1 stop is 1, and Reinhard of 1 is 1/2; the other order would give 2/3.
  EXPECT_FLOAT_EQ(display_value(0.5f, transform(1.0f, ToneCurve::reinhard)), 0.5f);
  // ACES of 2 x 0.5: 0.8037975, not 2 x ACES(0.5) = 2 x 0.6163 (clamped to 1).
  EXPECT_NEAR(display_value(0.5f, transform(1.0f, ToneCurve::aces)), 0.8037975, 1e-6);
}

TEST(DisplayTransform, TheEncodingComesAfterTheClamp) {
  // sRGB of 0.5: 1.055 x 0.5^(1/2.4) - 0.055 = 0.7353570.
  EXPECT_NEAR(display_value(1.0f, transform(0.0f, ToneCurve::reinhard, true)), 0.735357, 1e-6);
  // Clamped first: 2 shows as sRGB(1) = 1, not as 1.055 x 2^(1/2.4) - 0.055 = 1.3.
  EXPECT_NEAR(display_value(2.0f, transform(0.0f, ToneCurve::none, true)), 1.0, 1e-6);
  EXPECT_NEAR(display_encode(0.002f, true), 0.02584, 1e-6);  // the linear segment, 12.92 x
  EXPECT_FLOAT_EQ(display_linear(0.5f, transform(0.0f, ToneCurve::none, true)), 0.5f);
}

TEST(DisplayTransform, BytesRoundToNearest) {
  const DisplayTransform none = transform(0.0f, ToneCurve::none);
  EXPECT_EQ(display_byte(0.5f, none), 128);  // 127.5 rounds up
  EXPECT_EQ(display_byte(0.25f, none), 64);  // 63.75
  EXPECT_EQ(display_byte(1.7f, none), 255);
  // Reinhard of 1 at 0 stops: 0.5 -> 128; at -1 stop: 0.5 / 1.5 = 1/3 -> 85.
  EXPECT_EQ(display_byte(1.0f, transform(0.0f, ToneCurve::reinhard)), 128);
  EXPECT_EQ(display_byte(1.0f, transform(-1.0f, ToneCurve::reinhard)), 85);
  // sRGB of 0.5: 187.516 -> 188.
  EXPECT_EQ(display_byte(0.5f, transform(0.0f, ToneCurve::none, true)), 188);
}

TEST(DisplayTransform, EncodingOnlyKeepsTheEncoding) {
  const DisplayTransform e = encoding_only(transform(2.0f, ToneCurve::aces, true));
  EXPECT_EQ(e.gain, 1.0f);
  EXPECT_EQ(e.tone, ToneCurve::none);
  EXPECT_TRUE(e.srgb);
}

TEST(DisplayTransform, TheBatchLoopsAgreeWithTheScalarFunctions) {
  std::vector<float> in;
  for (int i = -20; i <= 400; ++i) in.push_back(0.037f * static_cast<float>(i));
  in.push_back(std::numeric_limits<float>::quiet_NaN());
  in.push_back(std::numeric_limits<float>::infinity());
  for (ToneCurve tone : {ToneCurve::none, ToneCurve::reinhard, ToneCurve::aces}) {
    for (bool srgb : {false, true}) {
      const DisplayTransform d = transform(0.7f, tone, srgb);
      std::vector<float> out(in.size());
      display_values(in.data(), out.data(), in.size(), d);
      Image image(static_cast<int>(in.size()), 1);
      for (std::size_t i = 0; i < in.size(); ++i) image.pixels[i] = glm::vec3(in[i]);
      const Image shown = displayed_image(image, d);
      const std::vector<unsigned char> bytes = display_bytes(image, d);
      for (std::size_t i = 0; i < in.size(); ++i) {
        const float v = display_value(in[i], d);
        EXPECT_GE(v, 0.0f);
        EXPECT_LE(v, 1.0f);
        EXPECT_NEAR(out[i], v, 1e-6f) << in[i];
        EXPECT_NEAR(shown.pixels[i].y, v, 1e-6f) << in[i];
        EXPECT_EQ(bytes[i * 3 + 2], display_byte(in[i], d)) << in[i];
      }
    }
  }
}

}  // namespace
}  // namespace gloss

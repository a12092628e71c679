// The exponent's logarithmic drag: a pixel is 1% of the value anywhere on the range.
#include <gtest/gtest.h>

#include <cmath>

#include "editor/model/view/log_drag.h"

namespace gloss {
namespace {

TEST(LogDrag, APixelIsOnePercentOfTheValueAnywhereOnTheRange) {
  // The old slider: ln(10000 / 0.1) over ~150 px = 8% per pixel. Now 1% at every value.
  EXPECT_FLOAT_EQ(log_drag_speed(5.0f, 0.01f), 0.05f);
  EXPECT_FLOAT_EQ(log_drag_speed(5000.0f, 0.01f), 50.0f);
  EXPECT_FLOAT_EQ(log_drag_speed(0.0f, 0.01f), 0.01f);  // the floor lets a drag leave 0
  // 100 px to the right from 51.2 multiply it by about 1.01^100 = 2.7 (frame by frame).
  float v = 51.2f;
  for (int px = 0; px < 100; ++px) v += log_drag_speed(v, 0.01f);
  EXPECT_NEAR(v, 51.2f * std::pow(1.01f, 100.0f), 0.01f);
}

}  // namespace
}  // namespace gloss

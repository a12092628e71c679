// The exponent's logarithmic drag: a pixel is 1% of the value anywhere on the range, and the
// value follows the mouse's distance from the press, so it returns to its start with the mouse.
#include <gtest/gtest.h>

#include <cmath>

#include "editor/model/view/log_drag.h"

namespace gloss {
namespace {

constexpr float kLo = 0.0f, kHi = 10000.0f, kFloor = 0.01f;

float drag(float start, float dx) {
  return log_drag_value(start, dx, kLogDragPerPixel, kFloor, kLo, kHi);
}

TEST(LogDrag, APixelIsOnePercentOfTheValueAnywhereOnTheRange) {
  // The old slider: ln(10000 / 0.1) over ~150 px = 8% per pixel. Now about 1% at every value:
  // (v + c) 1.01 - c with c = 0.01 / ln(1.01) = 1.005: 5 -> 5.06, 5000 -> 5050.01.
  EXPECT_NEAR(drag(5.0f, 1.0f), 5.0f + 0.01f * (5.0f + 1.005f), 1e-4f);
  EXPECT_NEAR(drag(5000.0f, 1.0f), 5050.01f, 0.01f);
  // 100 px to the right from 51.2: (52.205) 1.01^100 - 1.005 = 140.82.
  EXPECT_NEAR(drag(51.2f, 100.0f), 52.205f * std::pow(1.01f, 100.0f) - 1.005f, 0.01f);
  EXPECT_GT(drag(0.0f, 10.0f), 0.09f);  // the floor lets a drag leave 0: about 0.1 in 10 px
}

TEST(LogDrag, TheValueReturnsToItsStartWithTheMouse) {
  // The afternoon's bug: 1% of the current value per frame, +N then -N pixels, ends lower
  // (51.2 x 1.01^100 x 0.99^100 = 50.69). Now the value depends on the distance alone.
  for (float start : {0.0f, 1.0f, 51.2f, 128.0f, 9999.0f}) {
    EXPECT_EQ(drag(start, 0.0f), start);
    // Any path of mouse positions: the value at each is a function of the position alone.
    const float out = drag(start, 137.0f);
    EXPECT_EQ(drag(start, 137.0f), out);
    EXPECT_GE(drag(start, 50.0f), drag(start, -50.0f));
  }
  EXPECT_EQ(drag(51.2f, 0.0f), 51.2f);
}

TEST(LogDrag, ClampsAndModifiers) {
  EXPECT_EQ(drag(9000.0f, 500.0f), kHi);
  EXPECT_EQ(drag(2.0f, -5000.0f), kLo);
  EXPECT_FLOAT_EQ(log_drag_per_pixel(false, false), 0.01f);
  EXPECT_FLOAT_EQ(log_drag_per_pixel(true, false), 0.1f);
  EXPECT_FLOAT_EQ(log_drag_per_pixel(false, true), 0.001f);
}

}  // namespace
}  // namespace gloss

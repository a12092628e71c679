// The editor's measure of continuous edits (image_cadence.h) on event sequences worked out by
// hand: each image's delay measured from the edit of its generation, gaps between images with
// the open one at the end of the window counted.
#include "editor/model/measure/image_cadence.h"

#include <gtest/gtest.h>

namespace gloss {
namespace {

TEST(ImageCadence, ASingleEditIsMeasuredToItsFirstAndItsFullSizeImage) {
  ImageCadence c;
  c.edit(1, 10.0);
  ImageCadence::Delays d = c.shown(1, false, 10.004);  // a preview
  EXPECT_NEAR(d.first_ms, 4.0, 1e-9);
  EXPECT_EQ(d.full_ms, -1.0);
  d = c.shown(1, true, 10.020);  // the full-size image
  EXPECT_EQ(d.first_ms, -1.0);
  EXPECT_NEAR(d.full_ms, 20.0, 1e-9);
  d = c.shown(1, true, 10.050);  // a refinement pass: completes nothing
  EXPECT_EQ(d.first_ms, -1.0);
  EXPECT_EQ(d.full_ms, -1.0);
}

// The A/B snapshot | live view: an edit of side A's renderer (generation 7) is not shown when
// the next edit changes side B alone, whose renderer counts from 1. After forget_pending, B's
// frame 2 is measured from B's edit, not from A's older one.
TEST(ImageCadence, ForgottenEditsCountInNoDelay) {
  ImageCadence c;
  c.edit(7, 1.0);
  c.forget_pending();
  c.edit(2, 1.5);
  ImageCadence::Delays d = c.shown(1, true, 1.6);  // B's frame of the scene before the edit
  EXPECT_EQ(d.first_ms, -1.0);
  EXPECT_EQ(d.full_ms, -1.0);
  d = c.shown(2, true, 1.7);
  EXPECT_NEAR(d.first_ms, 200.0, 1e-9);
  EXPECT_NEAR(d.full_ms, 200.0, 1e-9);
  d = c.shown(7, true, 1.8);  // a frame of generation 7 completes no forgotten edit
  EXPECT_EQ(d.first_ms, -1.0);
}

// Edits every 16 ms, frames that each show the newest edit taken when they began: each image is
// measured from the edit of its own generation.
TEST(ImageCadence, EditsFasterThanFramesAreMeasuredFromTheOldestTheyShow) {
  ImageCadence c;
  c.restart(0.0);
  c.edit(1, 0.000);
  c.edit(2, 0.016);
  c.edit(3, 0.032);
  ImageCadence::Delays d = c.shown(2, true, 0.050);  // shows edits 1 and 2
  EXPECT_NEAR(d.first_ms, 34.0, 1e-9);
  EXPECT_NEAR(d.full_ms, 34.0, 1e-9);
  EXPECT_EQ(d.generation, 2u);
  d = c.shown(3, false, 0.070);  // edit 3, a preview
  EXPECT_NEAR(d.first_ms, 38.0, 1e-9);
  d = c.shown(3, true, 0.100);
  EXPECT_NEAR(d.full_ms, 68.0, 1e-9);
  // Gaps: 50 (window start to the first image), 20, 30, and 200 open at 0.3 s.
  const ImageCadence::Window w = c.window(0.3);
  EXPECT_EQ(w.images, 3);
  EXPECT_NEAR(w.max_gap_ms, 200.0, 1e-9);
  EXPECT_NEAR(w.median_gap_ms, 50.0, 1e-9);  // upper middle of 20, 30, 50, 200
  EXPECT_EQ(w.delays, 2);
  EXPECT_NEAR(w.median_delay_ms, 38.0, 1e-9);  // upper middle of 34, 38
  EXPECT_NEAR(w.max_delay_ms, 38.0, 1e-9);
  EXPECT_NEAR(w.seconds, 0.3, 1e-12);
}

TEST(ImageCadence, AFrozenImageIsOneGapAsLongAsTheWindow) {
  ImageCadence c;
  c.restart(5.0);
  for (int k = 0; k < 100; ++k) c.edit(static_cast<std::uint64_t>(k + 1), 5.0 + 0.016 * k);
  const ImageCadence::Window w = c.window(13.0);
  EXPECT_EQ(w.images, 0);
  EXPECT_NEAR(w.max_gap_ms, 8000.0, 1e-6);
  EXPECT_EQ(w.delays, 0);
}

TEST(ImageCadence, RestartBeginsANewWindowAndKeepsTheEditsPending) {
  ImageCadence c;
  c.edit(1, 1.0);
  c.shown(1, true, 1.1);
  c.edit(2, 1.2);
  c.restart(2.0);
  const ImageCadence::Delays d = c.shown(ImageCadence::kNewest, true, 2.5);  // a raster frame
  EXPECT_NEAR(d.first_ms, 1300.0, 1e-9);
  EXPECT_EQ(d.generation, 2u);
  const ImageCadence::Window w = c.window(3.0);
  EXPECT_EQ(w.images, 1);
  EXPECT_NEAR(w.max_gap_ms, 500.0, 1e-9);  // 500 to the image, then 500 open
  EXPECT_EQ(w.delays, 1);
}

}  // namespace
}  // namespace gloss

// Stratified sample positions: each sample in its own cell of the square grid for every square
// count up to the largest spp, and the 16-lane form equal to the one-sample form.
#include <gtest/gtest.h>

#include "scene/render_settings.h"
#include "shading/sampling.h"

namespace gloss {
namespace {

TEST(SampleOffsets, EverySquarePatternPutsEachStratumInItsOwnCell) {
  for (int side = 2; side * side <= kMaxSpp; ++side) {
    const SamplePattern p = make_sample_pattern(7, side * side);
    ASSERT_TRUE(p.square);
    for (int stratum = 0; stratum < p.count; ++stratum) {
      for (const auto& [x, y] : {std::pair<int, int>{0, 0}, {17, 3}, {1279, 719}}) {
        const SampleOffset o = sample_offset(p, stratum, x, y);
        ASSERT_EQ(static_cast<int>(o.dx * static_cast<float>(side)), stratum % side)
            << side << " " << stratum;
        ASSERT_EQ(static_cast<int>(o.dy * static_cast<float>(side)), stratum / side)
            << side << " " << stratum;
      }
    }
  }
}

TEST(SampleOffsets, LanesEqualOneSampleAtATime) {
  for (const int count : {1, 5, 16, 64}) {  // centre, N-rooks, squares
    const SamplePattern p = make_sample_pattern(3, count);
    int stratum[16], x[16], y[16];
    for (int i = 0; i < 16; ++i) {
      stratum[i] = (i * 7) % count;
      x[i] = 100 + i;
      y[i] = 40 + i / 4;
    }
    SampleOffset lanes[16];
    sample_offsets(p, stratum, x, y, 16, lanes);
    for (int i = 0; i < 16; ++i) {
      const SampleOffset one = sample_offset(p, stratum[i], x[i], y[i]);
      EXPECT_EQ(lanes[i].dx, one.dx) << count << " " << i;
      EXPECT_EQ(lanes[i].dy, one.dy) << count << " " << i;
    }
  }
}

}  // namespace
}  // namespace gloss

#pragma once
// What the display transform (display/display_transform.h; shaders/display.frag on screen) does
// to an image: exposure, tone curve, clamp to [0, 1], then as is (classic clamp) or sRGB. The
// histogram counts the displayed values; the clipped share counts the pixels the clamp changed at
// the top. A pixel is clipped when ANY channel's exposed and tone-mapped value is above 1 (per
// channel, not luminance: a saturated red highlight is clipped even when its luminance is not);
// Reinhard's curve never reaches 1, ACES's does from 7.24 on.
#include <array>
#include <cstdint>
#include <string>

#include "base/image.h"
#include "display/display_transform.h"

namespace gloss {

struct ExposureHistogram {
  static constexpr int kBins = 64;  // over the displayed value 0..1
  // counts[c][b]: pixels whose displayed channel c (0 R, 1 G, 2 B) falls in bin b; a value of
  // exactly 1 counts in the last bin.
  std::array<std::array<std::uint32_t, kBins>, 3> counts{};
  std::uint64_t pixels = 0;  // pixels counted in the bins
  // Every pixel of the image, sampled or not: the clipped counts below are exact.
  std::uint64_t all_pixels = 0;
  std::uint64_t clipped = 0;                       // pixels with any channel clipped
  std::array<std::uint64_t, 3> clipped_channel{};  // per channel: above 1 before the clamp

  // Share of the image's pixels with a clipped channel, 0..1 (0 for an empty image).
  double clipped_share() const;
  // The same for channel c alone.
  double clipped_channel_share(int c) const;
};

// Histogram of image as displayed through display. step > 1 counts every step-th pixel of every
// step-th row (the viewport uses it to stay cheap on big images; the `stats` line and the tests
// count every pixel).
ExposureHistogram exposure_histogram(const Image& image, const DisplayTransform& display,
                                     int step = 1);

// A share 0..1 as the panel and `stats` print it: "0%" only when nothing is clipped, "< 0.1%"
// for a share that one decimal would round to 0, else one decimal ("12.5%").
std::string clipped_text(double share);

}  // namespace gloss

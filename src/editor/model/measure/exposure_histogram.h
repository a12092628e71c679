#pragma once
// What the viewport's display transform does to an image (shaders/display.frag): linear RGB
// times 2^exposure, clamped to [0, 1], then written as is (classic clamp) or sRGB-encoded. The
// histogram counts the displayed values; the clipped share counts the pixels the clamp changed
// at the top. A pixel is clipped when ANY channel's exposed linear value is above 1 (per channel,
// not luminance: a saturated red highlight is clipped even when its luminance is not).
#include <array>
#include <cstdint>

#include "base/image.h"

namespace gloss {

struct ExposureHistogram {
  static constexpr int kBins = 64;  // over the displayed value 0..1
  // counts[c][b]: pixels whose displayed channel c (0 R, 1 G, 2 B) falls in bin b; a value of
  // exactly 1 counts in the last bin.
  std::array<std::array<std::uint32_t, kBins>, 3> counts{};
  std::uint64_t pixels = 0;                        // pixels counted
  std::uint64_t clipped = 0;                       // pixels with any channel above 1 after exposure
  std::array<std::uint64_t, 3> clipped_channel{};  // per channel: above 1 after exposure

  // Share of counted pixels with a clipped channel, 0..1 (0 when nothing was counted).
  double clipped_share() const;
};

// The displayed value of one linear channel: clamp(linear * gain, 0, 1), sRGB-encoded when
// srgb. gain = 2^exposure_stops. NaN shows as 0, as the PNG writer does.
float display_value(float linear, float gain, bool srgb);

// Histogram of image as displayed at exposure_stops with the given encoding. step > 1 counts
// every step-th pixel of every step-th row (the viewport uses it to stay cheap on big images;
// the `stats` line and the tests count every pixel).
ExposureHistogram exposure_histogram(const Image& image, float exposure_stops, bool srgb,
                                     int step = 1);

}  // namespace gloss

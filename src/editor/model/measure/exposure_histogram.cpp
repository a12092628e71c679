#include "editor/model/measure/exposure_histogram.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace gloss {

namespace {

// Display-linear values (exposed, tone-mapped, clamped) at which the displayed value reaches bin
// b's lower edge, b = 1..kBins-1: the encoding is monotonic, so a pixel's bin is found by a
// binary search over these instead of a pow per channel (about 3 x cheaper on a viewport-sized
// image).
struct BinEdges {
  std::array<float, ExposureHistogram::kBins - 1> linear{};
  explicit BinEdges(bool srgb) {
    for (int b = 1; b < ExposureHistogram::kBins; ++b) {
      const float display = static_cast<float>(b) / ExposureHistogram::kBins;
      // The inverse of the encoding; values at an edge go to the upper bin, as floor would.
      float v = display;
      if (srgb)
        v = display <= 0.04045f ? display / 12.92f : std::pow((display + 0.055f) / 1.055f, 2.4f);
      linear[b - 1] = v;
    }
  }
  int bin(float exposed) const {
    return static_cast<int>(std::upper_bound(linear.begin(), linear.end(), exposed) -
                            linear.begin());
  }
};

}  // namespace

double ExposureHistogram::clipped_share() const {
  return all_pixels > 0 ? static_cast<double>(clipped) / static_cast<double>(all_pixels) : 0.0;
}

double ExposureHistogram::clipped_channel_share(int c) const {
  return all_pixels > 0 ? static_cast<double>(clipped_channel[static_cast<std::size_t>(c)]) /
                              static_cast<double>(all_pixels)
                        : 0.0;
}

ExposureHistogram exposure_histogram(const Image& image, const DisplayTransform& display,
                                     int step) {
  ExposureHistogram h;
  step = std::max(step, 1);
  const BinEdges edges(display.srgb);
  for (int y = 0; y < image.height; y += step) {
    const glm::vec3* row = image.pixels.data() + static_cast<std::size_t>(y) * image.width;
    for (int x = 0; x < image.width; x += step) {
      for (int c = 0; c < 3; ++c) ++h.counts[c][edges.bin(display_linear(row[x][c], display))];
      ++h.pixels;
    }
  }
  // The clipped pixels are counted in every pixel, whatever the step: a highlight of a few
  // pixels falls between the sampled ones, and the overlay shows it.
  const float level = clip_level(display);
  for (const glm::vec3& p : image.pixels) {
    const bool r = p.x > level, g = p.y > level, b = p.z > level;
    h.clipped_channel[0] += r ? 1 : 0;
    h.clipped_channel[1] += g ? 1 : 0;
    h.clipped_channel[2] += b ? 1 : 0;
    h.clipped += (r || g || b) ? 1 : 0;
  }
  h.all_pixels = image.pixels.size();
  return h;
}

std::string clipped_text(double share) {
  char text[32];
  if (share <= 0.0) return "0%";
  if (share < 0.0005) return "< 0.1%";
  std::snprintf(text, sizeof text, "%.1f%%", 100.0 * share);
  return text;
}

}  // namespace gloss

#include "analysis/image/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace gloss {

namespace {
// One 8-bit display step on linear values of order 1.
constexpr double kOffThreshold = 1.0 / 255.0;

ImageMetrics compare(const Image& test, const Image& reference,
                     const std::vector<std::uint8_t>* mask, std::uint8_t which) {
  if (test.width != reference.width || test.height != reference.height) {
    throw std::invalid_argument("compare_images: sizes differ");
  }
  if (mask != nullptr && mask->size() != reference.pixels.size()) {
    throw std::invalid_argument("compare_images: mask size differs from the image");
  }
  const double inf = std::numeric_limits<double>::infinity();
  ImageMetrics m;
  double sum_sq = 0;  // double: a million pixels of float squares would lose digits in float
  std::size_t off = 0;
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
    if (mask != nullptr && (*mask)[i] != which) continue;
    ++m.pixels;
    bool pixel_off = false;
    for (int c = 0; c < 3; ++c) {
      const double a = test.pixels[i][c], b = reference.pixels[i][c];
      double d = std::abs(a - b);
      if (!std::isfinite(d)) d = a == b ? 0.0 : inf;  // equal infinities agree
      sum_sq += d * d;
      m.max_abs = std::max(m.max_abs, d);
      pixel_off = pixel_off || d > kOffThreshold;
    }
    off += pixel_off ? 1 : 0;
  }
  if (m.pixels == 0) return m;
  const double mse = sum_sq / (3.0 * static_cast<double>(m.pixels));
  m.rmse = std::sqrt(mse);
  m.psnr_db = mse > 0.0 ? -10.0 * std::log10(mse) : inf;
  m.pct_pixels_off = 100.0 * static_cast<double>(off) / static_cast<double>(m.pixels);
  return m;
}
}  // namespace

ImageMetrics compare_images(const Image& test, const Image& reference) {
  return compare(test, reference, nullptr, 0);
}

ImageMetrics compare_images(const Image& test, const Image& reference,
                            const std::vector<std::uint8_t>& mask, std::uint8_t which) {
  return compare(test, reference, &mask, which);
}

std::string psnr_text(double psnr_db) {
  if (std::isinf(psnr_db)) return psnr_db > 0 ? "inf" : "-inf";
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", psnr_db);
  return text;
}

double relative_rmse(const Image& test, const Image& reference,
                     const std::vector<std::uint8_t>& mask) {
  if (test.width != reference.width || test.height != reference.height ||
      mask.size() != reference.pixels.size()) {
    throw std::invalid_argument("relative_rmse: sizes differ");
  }
  double squares = 0.0, sum = 0.0;  // double: a million float squares would lose digits
  std::size_t count = 0;
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
    if (mask[i] == 0) continue;
    for (int c = 0; c < 3; ++c) {
      const double d = double(test.pixels[i][c]) - reference.pixels[i][c];
      squares += d * d;
      sum += reference.pixels[i][c];
    }
    count += 3;
  }
  if (count == 0 || !(sum > 0.0)) return 0.0;
  return std::sqrt(squares / double(count)) / (sum / double(count));
}

double percent_within(const Image& test, const Image& reference, double tolerance) {
  if (test.width != reference.width || test.height != reference.height) {
    throw std::invalid_argument("percent_within: image sizes differ");
  }
  if (test.pixels.empty()) return 0.0;
  std::size_t within = 0;
  for (std::size_t i = 0; i < test.pixels.size(); ++i) {
    bool ok = true;
    for (int c = 0; c < 3; ++c) {
      const double d = std::fabs(double(test.pixels[i][c]) - double(reference.pixels[i][c]));
      ok = ok && d <= tolerance;  // NaN fails the comparison
    }
    within += ok ? 1 : 0;
  }
  return 100.0 * static_cast<double>(within) / static_cast<double>(test.pixels.size());
}

}  // namespace gloss

#pragma once
// How far an image is from a reference: the error figures of gloss-cli tradeoff. All figures are
// taken on linear values as rendered (unclamped, no display encoding), over the three channels of
// every pixel: silhouette and shadow-edge pixels are counted like any other, never left out.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "base/image.h"

namespace gloss {

struct ImageMetrics {
  double rmse = 0;            // sqrt(mean over pixels and channels of difference^2)
  double psnr_db = 0;         // 10 log10(1 / mse): peak 1 (linear), +inf for equal images
  double max_abs = 0;         // largest |difference| of any channel of any pixel
  double pct_pixels_off = 0;  // % of pixels with some channel off by more than 1/255
  std::size_t pixels = 0;     // pixels compared
};

// A non-finite value in test where reference is finite counts as an infinite difference (rmse
// and max_abs +inf, psnr -inf, the pixel off). Throws std::invalid_argument when the sizes differ.
ImageMetrics compare_images(const Image& test, const Image& reference);

// The same over the pixels whose mask entry equals which (mask: one entry per pixel, such as
// ReferenceOptions::edges); pixels = 0 and every figure 0 when none does.
ImageMetrics compare_images(const Image& test, const Image& reference,
                            const std::vector<std::uint8_t>& mask, std::uint8_t which);

// The relative RMSE of docs/accuracy.md ("Relative RMSE"): the RMSE over the pixels whose mask
// entry is not 0 and their three channels, over the mean of reference there (mask: one entry
// per pixel, such as ReferenceOptions::hits, the surface pixels). 0 when no pixel counts or that
// mean is 0. Throws std::invalid_argument when the sizes differ.
double relative_rmse(const Image& test, const Image& reference,
                     const std::vector<std::uint8_t>& mask);

// % of pixels of test whose every channel is within tolerance of reference (a non-finite value
// disagrees); 0 for empty images. Throws std::invalid_argument when the sizes differ.
double percent_within(const Image& test, const Image& reference, double tolerance);

// A PSNR as the CSV files and tables print it: "%.3f", or "inf" / "-inf".
std::string psnr_text(double psnr_db);

}  // namespace gloss

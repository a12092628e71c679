#pragma once
// The formats of image_reader.h, one reader each, and the checks they share (io's own,
// private).
#include <cstdint>
#include <string>

#include "io/image/image_reader.h"

namespace gloss {

FloatImage read_png_image(const std::string& path, const ImageReadOptions& options,
                          ImageFileInfo& info);
FloatImage read_hdr_image(const std::string& path, const ImageReadOptions& options,
                          ImageFileInfo& info);
FloatImage read_jpeg_image(const std::string& path, const ImageReadOptions& options,
                           ImageFileInfo& info);
FloatImage read_exr_image(const std::string& path, const ImageReadOptions& options,
                          ImageFileInfo& info);

// The budget in force: options.budget_bytes or memory_budget_bytes().
std::uint64_t image_budget(const ImageReadOptions& options);

// Refuses, naming path and format, a header of width x height x channels that is empty, wider
// or taller than kMaxMapSide, or whose floats (plus extra_bytes the reader needs beside them)
// do not fit the budget. Called before anything is allocated for the pixels.
void check_image_size(const std::string& path, const char* format, long long width,
                      long long height, int channels, const ImageReadOptions& options,
                      std::uint64_t extra_bytes = 0);

// Refuses an image holding a sample that is NaN or infinite, naming the first.
void check_finite_samples(const std::string& path, const FloatImage& image);

}  // namespace gloss

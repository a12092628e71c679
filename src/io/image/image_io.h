#pragma once
// Writing images: PFM (linear float, unclamped) and 8-bit PNG with text chunks. Every write goes
// to a temporary file that is renamed into place, so a failure never leaves a partial file.
#include <string>
#include <utility>
#include <vector>

#include "base/image.h"
#include "display/display_transform.h"

namespace gloss {

using TextChunks = std::vector<std::pair<std::string, std::string>>;  // keyword, text

// PF, little-endian (scale -1.0), scanlines bottom to top. Throws RuntimeFailure.
void write_pfm(const std::string& path, const Image& image);
// Reads what write_pfm writes (either endianness). Throws InputError.
Image read_pfm(const std::string& path);

// 8-bit RGB: each channel through the display transform (display/display_transform.h:
// exposure, tone curve, clamp to [0, 1], as is or sRGB-encoded), rounded to nearest. Text chunks
// are stored as PNG tEXt/zTXt. Throws RuntimeFailure.
void write_png(const std::string& path, const Image& image, const DisplayTransform& display,
               const TextChunks& text = {});
// The same with the encoding alone: clamped, then as is (srgb = false, the classic look) or
// sRGB-encoded.
void write_png(const std::string& path, const Image& image, bool srgb = false,
               const TextChunks& text = {});
// 8-bit RGB pixels (0..255) and the text chunks of a PNG. Throws InputError.
struct Png8 {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  // width * height * 3, top row first
  TextChunks text;
};
Png8 read_png(const std::string& path);

// One display value: the PNG encoding of a linear channel value, 0..255 (display_byte with the
// encoding alone).
unsigned char encode_channel(float linear, bool srgb);

}  // namespace gloss

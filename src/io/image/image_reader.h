#pragma once
// Map images read into linear float (base/float_image.h): PNG (8 and 16 bits, every colour type,
// through libpng), JPEG (libjpeg-turbo), Radiance HDR (stb_image) and OpenEXR (the OpenEXR library:
// Blender's studio lights are DWAB-compressed). Environment maps and textures read them; each
// reader checks the size its header claims against the limits and the memory budget
// (base/memory_budget.h) before it allocates, and refuses samples that are not finite. Every
// failure is an InputError naming the file, in one line.
#include <cstdint>
#include <string>

#include "base/float_image.h"

namespace gloss {

// The largest side a map may have, pixels; the memory budget usually refuses much less.
inline constexpr int kMaxMapSide = 32768;

enum class ImageData {
  colour,  // colour data: 8- and 16-bit PNG samples sRGB-decoded unless the file says linear
  linear,  // data (heights, exponents, normals): samples as stored, byte / 255, word / 65535
};

struct ImageReadOptions {
  ImageData data = ImageData::colour;
  // The decoded floats (and the reader's own copy of the file's bytes, for stb), plus
  // extra_bytes_per_pixel for what the caller makes of each pixel, must fit in this many bytes;
  // 0: memory_budget_bytes().
  std::uint64_t budget_bytes = 0;
  std::uint64_t extra_bytes_per_pixel = 0;
};

// What the file held, besides its samples.
struct ImageFileInfo {
  std::string format;         // "PNG", "JPEG", "Radiance HDR", "OpenEXR"
  int bits = 0;               // per sample as stored: 1 to 16 (PNG), 8 (JPEG), 32 (HDR: RGBE),
                              // 16 or 32 (EXR)
  bool srgb_decoded = false;  // the samples went through the sRGB curve
};

// Reads path, whichever of the formats its first bytes say it is (not its extension).
// Alpha is never sRGB-decoded. Throws InputError.
FloatImage read_image(const std::string& path, const ImageReadOptions& options = {},
                      ImageFileInfo* info = nullptr);

// read_image of an image held in memory (a model's embedded image); `name` stands for the file
// in messages.
FloatImage read_image_bytes(const std::string& bytes, const std::string& name,
                            const ImageReadOptions& options = {}, ImageFileInfo* info = nullptr);

// The sRGB curve's inverse: an encoded value in [0, 1] to linear.
float srgb_to_linear(float encoded);

}  // namespace gloss

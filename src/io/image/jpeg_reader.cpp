// read_jpeg_image (map_readers.h): baseline and progressive JPEG through stb_image (libstb-dev),
// grey or colour (CMYK files come out as RGB), 8 bits per sample. A JPEG says nothing about its
// encoding, so colour maps take it as sRGB, as every painting tool writes it.
#include <stb_image.h>

#include <memory>
#include <string>
#include <vector>

#include "base/error.h"
#include "io/image/map_readers.h"
#include "io/image/stb_memory.h"

namespace gloss {

FloatImage read_jpeg_image(const std::string& path, const ImageReadOptions& options,
                           ImageFileInfo& info) {
  info.format = "JPEG";
  info.bits = 8;
  // stb reads from memory: the file's bytes count against the budget with the floats.
  const std::vector<stbi_uc> bytes = read_file_bytes(path, "JPEG", options);
  const int length = static_cast<int>(bytes.size());
  int width = 0, height = 0, channels = 0;
  if (stbi_info_from_memory(bytes.data(), length, &width, &height, &channels) == 0) {
    const char* reason = stbi_failure_reason();
    throw InputError(
        path, std::string("invalid JPEG: ") + (reason != nullptr ? reason : "unreadable header"));
  }
  const std::uint64_t decoded = static_cast<std::uint64_t>(width) * height * channels;
  check_image_size(path, "JPEG", width, height, channels, options, bytes.size() + decoded);
  StbMemory reader(bytes);
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load_from_callbacks(&StbMemory::callbacks(), &reader, &width, &height, &channels, 0),
      &stbi_image_free);
  if (pixels && reader.ran_out) {
    throw InputError(path, "invalid JPEG: the image data is truncated (" +
                               std::to_string(bytes.size()) + " bytes)");
  }
  if (!pixels) {
    const char* reason = stbi_failure_reason();
    throw InputError(
        path, std::string("invalid JPEG: ") + (reason != nullptr ? reason : "cannot decode"));
  }
  const bool decode = options.data == ImageData::colour;
  info.srgb_decoded = decode;
  float table[256];
  for (int v = 0; v < 256; ++v) {
    const float plain = static_cast<float>(v / 255.0);
    table[v] = decode ? srgb_to_linear(plain) : plain;
  }
  FloatImage image;
  image.width = width;
  image.height = height;
  image.channels = channels;
  image.samples.resize(static_cast<std::size_t>(width) * height * channels);
  for (std::size_t i = 0; i < image.samples.size(); ++i) image.samples[i] = table[pixels.get()[i]];
  return image;
}

}  // namespace gloss

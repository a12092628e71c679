// read_hdr_image (map_readers.h): Radiance HDR (RGBE) through stb_image, which gives linear
// floats for it (its 8-bit paths apply a gamma of 2.2, not the sRGB curve: gloss reads 8-bit
// images through libpng instead).
#include <stb_image.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "base/error.h"
#include "io/image/map_readers.h"
#include "io/image/stb_memory.h"

namespace gloss {

FloatImage read_hdr_image(const std::string& path, const ImageReadOptions& options,
                          ImageFileInfo& info) {
  info.format = "Radiance HDR";
  info.bits = 32;
  // stb reads from memory: the file's bytes count against the budget with the floats.
  const std::vector<stbi_uc> bytes = read_file_bytes(path, "Radiance HDR", options);
  const int length = static_cast<int>(bytes.size());
  int width = 0, height = 0, channels = 0;
  if (stbi_is_hdr_from_memory(bytes.data(), length) == 0 ||
      stbi_info_from_memory(bytes.data(), length, &width, &height, &channels) == 0) {
    const char* reason = stbi_failure_reason();
    throw InputError(path, std::string("invalid Radiance HDR: ") +
                               (reason != nullptr ? reason : "unreadable header"));
  }
  check_image_size(path, "Radiance HDR", width, height, 3, options, bytes.size());
  StbMemory reader(bytes);
  std::unique_ptr<float, void (*)(void*)> pixels(
      stbi_loadf_from_callbacks(&StbMemory::callbacks(), &reader, &width, &height, &channels, 3),
      &stbi_image_free);
  if (pixels && reader.ran_out) {
    throw InputError(path, "invalid Radiance HDR: the pixel data is truncated (" +
                               std::to_string(bytes.size()) + " bytes)");
  }
  if (!pixels) {
    const char* reason = stbi_failure_reason();
    throw InputError(path, std::string("invalid Radiance HDR: ") +
                               (reason != nullptr ? reason : "cannot decode"));
  }
  FloatImage image;
  image.width = width;
  image.height = height;
  image.channels = 3;
  image.samples.assign(pixels.get(), pixels.get() + static_cast<std::size_t>(width) * height * 3);
  return image;
}

}  // namespace gloss

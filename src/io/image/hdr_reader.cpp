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

namespace gloss {

namespace {

// stb_image reads past the end of a truncated file as zeros without an error; it asks its
// callbacks for more when it does, which is how a truncated file is told from a whole one.
struct Reader {
  const std::vector<stbi_uc>* bytes = nullptr;
  std::size_t at = 0;
  bool ran_out = false;  // stb asked for bytes after the last one
};

int read_bytes(void* user, char* out, int size) {
  auto& r = *static_cast<Reader*>(user);
  const std::size_t n = std::min(static_cast<std::size_t>(size), r.bytes->size() - r.at);
  std::memcpy(out, r.bytes->data() + r.at, n);
  r.at += n;
  if (n == 0 && size > 0) r.ran_out = true;
  return static_cast<int>(n);
}

void skip_bytes(void* user, int n) {
  auto& r = *static_cast<Reader*>(user);
  if (n < 0) {
    r.at -= std::min(r.at, static_cast<std::size_t>(-static_cast<long long>(n)));
  } else {
    r.at = std::min(r.bytes->size(), r.at + static_cast<std::size_t>(n));
  }
}

int at_end(void* user) {
  const auto& r = *static_cast<const Reader*>(user);
  return r.at >= r.bytes->size() ? 1 : 0;
}

}  // namespace

FloatImage read_hdr_image(const std::string& path, const ImageReadOptions& options,
                          ImageFileInfo& info) {
  info.format = "Radiance HDR";
  info.bits = 32;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                       &std::fclose);
  if (!file) throw InputError(path, std::string("cannot read: ") + std::strerror(errno));
  // stb reads from memory: the file's bytes count against the budget with the floats.
  std::fseek(file.get(), 0, SEEK_END);
  const long size = std::ftell(file.get());
  std::fseek(file.get(), 0, SEEK_SET);
  if (size < 0) throw InputError(path, std::string("cannot read: ") + std::strerror(errno));
  if (static_cast<std::uint64_t>(size) > image_budget(options) ||
      size > std::numeric_limits<int>::max()) {
    throw InputError(path, "Radiance HDR file of " + std::to_string(size) +
                               " bytes is larger than the memory budget allows");
  }
  std::vector<stbi_uc> bytes(static_cast<std::size_t>(size));
  if (std::fread(bytes.data(), 1, bytes.size(), file.get()) != bytes.size()) {
    throw InputError(path, std::string("cannot read: ") + std::strerror(errno));
  }
  const int length = static_cast<int>(bytes.size());
  int width = 0, height = 0, channels = 0;
  if (stbi_is_hdr_from_memory(bytes.data(), length) == 0 ||
      stbi_info_from_memory(bytes.data(), length, &width, &height, &channels) == 0) {
    const char* reason = stbi_failure_reason();
    throw InputError(path, std::string("invalid Radiance HDR: ") +
                               (reason != nullptr ? reason : "unreadable header"));
  }
  check_image_size(path, "Radiance HDR", width, height, 3, options, bytes.size());
  Reader reader{&bytes};
  const stbi_io_callbacks callbacks = {read_bytes, skip_bytes, at_end};
  std::unique_ptr<float, void (*)(void*)> pixels(
      stbi_loadf_from_callbacks(&callbacks, &reader, &width, &height, &channels, 3),
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

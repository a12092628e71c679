#include "io/image/image_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include "base/error.h"
#include "base/memory_budget.h"
#include "io/image/map_readers.h"

namespace gloss {

namespace {

enum class Format { png, jpeg, hdr, exr, unknown };

// The format from the file's first bytes: PNG's 8-byte signature, JPEG's start-of-image marker
// and the next marker's first byte (FF D8 FF), Radiance's "#?" header
// (#?RADIANCE or #?RGBE), OpenEXR's magic number 20000630 (76 2f 31 01, little-endian).
Format sniff(const std::string& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                       &std::fclose);
  if (!file) throw InputError(path, std::string("cannot read: ") + std::strerror(errno));
  unsigned char head[8] = {};
  const std::size_t n = std::fread(head, 1, sizeof head, file.get());
  static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (n == 8 && std::memcmp(head, png, 8) == 0) return Format::png;
  if (n >= 3 && head[0] == 0xFF && head[1] == 0xD8 && head[2] == 0xFF) return Format::jpeg;
  if (n >= 2 && head[0] == '#' && head[1] == '?') return Format::hdr;
  if (n >= 4 && head[0] == 0x76 && head[1] == 0x2f && head[2] == 0x31 && head[3] == 0x01) {
    return Format::exr;
  }
  return Format::unknown;
}

}  // namespace

float srgb_to_linear(float encoded) {
  const double v = encoded;
  return static_cast<float>(v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
}

std::uint64_t image_budget(const ImageReadOptions& options) {
  return options.budget_bytes > 0 ? options.budget_bytes : memory_budget_bytes();
}

void check_image_size(const std::string& path, const char* format, long long width,
                      long long height, int channels, const ImageReadOptions& options,
                      std::uint64_t extra_bytes) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (width < 1 || height < 1) {
    throw InputError(path, std::string(format) + " image is empty (" + size + ")");
  }
  if (width > kMaxMapSide || height > kMaxMapSide) {
    throw InputError(path, std::string(format) + " image is " + size +
                               ", more than the largest map side of " +
                               std::to_string(kMaxMapSide) + " pixels");
  }
  const std::uint64_t bytes = static_cast<std::uint64_t>(width) * height *
                                  (channels * sizeof(float) + options.extra_bytes_per_pixel) +
                              extra_bytes;
  const std::uint64_t budget = image_budget(options);
  if (bytes > budget) {
    const std::string limit =
        options.budget_bytes > 0 ? std::to_string(megabytes(budget)) + " MB" : memory_budget_text();
    throw InputError(path, std::string(format) + " image of " + size + " pixels needs ~" +
                               std::to_string(megabytes(bytes)) +
                               " MB, more than the memory budget of " + limit);
  }
}

void check_finite_samples(const std::string& path, const FloatImage& image) {
  for (std::size_t i = 0; i < image.samples.size(); ++i) {
    if (std::isfinite(image.samples[i])) continue;
    const std::size_t pixel = i / static_cast<std::size_t>(image.channels);
    const auto x = static_cast<long long>(pixel % static_cast<std::size_t>(image.width));
    const auto y = static_cast<long long>(pixel / static_cast<std::size_t>(image.width));
    throw InputError(path, "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") holds " +
                               (std::isnan(image.samples[i]) ? "NaN" : "an infinite value") +
                               ": a map's samples must be finite numbers");
  }
}

FloatImage read_image(const std::string& path, const ImageReadOptions& options,
                      ImageFileInfo* info) {
  ImageFileInfo own;
  ImageFileInfo& out = info != nullptr ? *info : own;
  FloatImage image;
  switch (sniff(path)) {
    case Format::png:
      image = read_png_image(path, options, out);
      break;
    case Format::jpeg:
      image = read_jpeg_image(path, options, out);
      break;
    case Format::hdr:
      image = read_hdr_image(path, options, out);
      break;
    case Format::exr:
      image = read_exr_image(path, options, out);
      break;
    case Format::unknown:
      throw InputError(path,
                       "not an image gloss reads as a map (PNG, JPEG, Radiance HDR or OpenEXR, "
                       "told by the file's first bytes)");
  }
  check_finite_samples(path, image);
  return image;
}

}  // namespace gloss

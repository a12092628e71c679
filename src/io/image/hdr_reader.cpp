// read_hdr_image (map_readers.h): Radiance HDR (RGBE) through stb_image, which gives linear
// floats for it (its 8-bit paths apply a gamma of 2.2, not the sRGB curve: gloss reads 8-bit
// images through libpng instead). stb's decoder (stbi__hdr_load, v2.27) never ends on bad data:
// past the end it reads zeros, and a run count of 0 advances nothing, so a scan line cut short
// or holding a 0 keeps it looping forever. The pixel data is therefore walked here first, by
// stb's own rules, and refused where stb would loop or read past the end.
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

namespace {

// Where the pixels start, as stb reads the header: the identifier line, variable lines up to an
// empty one, the resolution line. A line runs through its '\n' (or to the end of the file); stb
// takes one that starts with '\n' or NUL, or is the file's last byte, as empty.
std::size_t pixels_start(const std::vector<stbi_uc>& bytes) {
  std::size_t at = 0;
  const auto next_line = [&]() {
    const bool empty = at + 1 >= bytes.size() || bytes[at] == '\n' || bytes[at] == '\0';
    const auto* end = std::find(bytes.data() + std::min(at, bytes.size()),
                                bytes.data() + bytes.size(), stbi_uc('\n'));
    at = std::min(bytes.size(), static_cast<std::size_t>(end - bytes.data()) + 1);
    return empty;
  };
  next_line();  // #?RADIANCE or #?RGBE
  while (!next_line()) {
  }
  next_line();  // -Y height +X width
  return at;
}

// Empty when stb will decode width x height pixels from bytes[at...] without reading past the
// end; else why not. stb reads flat RGBE pixels for widths under 8 or from 32768 on; else each
// scan line starts 2, 2, then its width in 2 bytes, and holds each channel in turn as runs
// (count - 128 times the next byte) and dumps (count bytes). A scan line starting otherwise
// sends stb back to pixel 1 of line 0, reading every other pixel flat. Every step consumes a
// byte, so this takes at most one pass over the file.
std::string pixel_data_problem(const std::vector<stbi_uc>& bytes, std::size_t at, int width,
                               int height) {
  const std::size_t size = bytes.size();
  const std::uint64_t pixels =
      static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  const auto flat = [&](std::uint64_t count) -> std::string {
    if ((size - at) / 4 >= count) return "";
    return "the pixel data is truncated (" + std::to_string(count) + " flat pixels need " +
           std::to_string(4 * count) + " bytes from byte " + std::to_string(at) +
           ", the file has " + std::to_string(size) + ")";
  };
  if (width < 8 || width >= 32768) return flat(pixels);
  const auto cut = [&](int line) {
    return "the pixel data is truncated (scan line " + std::to_string(line) + " of " +
           std::to_string(height) + " goes past the file's " + std::to_string(size) + " bytes)";
  };
  for (int line = 0; line < height; ++line) {
    if (size - at < 4) return cut(line);
    if (bytes[at] != 2 || bytes[at + 1] != 2 || (bytes[at + 2] & 0x80) != 0) {
      at += 4;
      return flat(pixels - 1);
    }
    const int declared = (bytes[at + 2] << 8) | bytes[at + 3];
    if (declared != width) {
      return "scan line " + std::to_string(line) + " at byte " + std::to_string(at) + " declares " +
             std::to_string(declared) + " pixels in a " + std::to_string(width) +
             "-pixel-wide image";
    }
    at += 4;
    for (int channel = 0; channel < 4; ++channel) {
      for (int x = 0; x < width;) {
        if (at >= size) return cut(line);
        const std::size_t start = at;
        int count = bytes[at++];
        const bool run = count > 128;
        if (run) count -= 128;
        const auto place = [&]() {
          return "scan line " + std::to_string(line) + ", channel " + std::to_string(channel) +
                 ", byte " + std::to_string(start);
        };
        if (count == 0) return place() + ": a dump of 0 bytes (stb would never finish the line)";
        if (count > width - x) {
          return place() + ": " + std::to_string(count) + " pixels pass the line's end";
        }
        const std::size_t stored = run ? 1 : static_cast<std::size_t>(count);
        if (size - at < stored) return cut(line);
        at += stored;
        x += count;
      }
    }
  }
  return "";
}

}  // namespace

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
  const std::string problem = pixel_data_problem(bytes, pixels_start(bytes), width, height);
  if (!problem.empty()) throw InputError(path, "invalid Radiance HDR: " + problem);
  StbMemory reader(bytes);
  std::unique_ptr<float, void (*)(void*)> pixels(
      stbi_loadf_from_callbacks(&StbMemory::callbacks(), &reader, &width, &height, &channels, 3),
      &stbi_image_free);
  // The walk above has refused data stb would read past; this catches any other stb build.
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

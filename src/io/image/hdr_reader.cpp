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
  const std::string problem = pixel_data_problem(bytes, pixels_start(bytes), width, height);
  if (!problem.empty()) throw InputError(path, "invalid Radiance HDR: " + problem);
  Reader reader{&bytes};
  const stbi_io_callbacks callbacks = {read_bytes, skip_bytes, at_end};
  std::unique_ptr<float, void (*)(void*)> pixels(
      stbi_loadf_from_callbacks(&callbacks, &reader, &width, &height, &channels, 3),
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

#include "io/image/image_io.h"

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>

#include "base/atomic_file.h"
#include "base/error.h"
#include "io/image/png_support.h"
#include "scene/render_settings.h"

namespace gloss {

namespace {

[[noreturn]] void fail_write(const std::string& path, const std::string& reason) {
  throw RuntimeFailure("cannot write " + path + ": " + reason);
}

void check_image_shape(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0) {
    fail_write(path, "image is empty (" + std::to_string(image.width) + "x" +
                         std::to_string(image.height) + ")");
  }
  if (image.pixels.size() != static_cast<std::size_t>(image.width) * image.height) {
    fail_write(path, "image is " + std::to_string(image.width) + "x" +
                         std::to_string(image.height) + " but holds " +
                         std::to_string(image.pixels.size()) + " pixels");
  }
}

// ---- PFM -------------------------------------------------------------------------------------

void append_float_le(std::string& out, float value) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<char>(bits >> shift));
}

float float_at(const std::string& bytes, std::size_t offset, bool little_endian) {
  std::uint32_t bits = 0;
  for (int i = 0; i < 4; ++i) {
    const auto byte = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[offset + i]));
    bits |= byte << (little_endian ? 8 * i : 8 * (3 - i));
  }
  float value = 0;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

// The next whitespace-separated header token; pos ends on the byte after it.
std::string next_token(const std::string& bytes, std::size_t& pos) {
  while (pos < bytes.size() && is_space(bytes[pos])) ++pos;
  const std::size_t start = pos;
  while (pos < bytes.size() && !is_space(bytes[pos])) ++pos;
  return bytes.substr(start, pos - start);
}

int parse_dimension(const std::string& path, const std::string& token, const char* what) {
  const bool digits =
      !token.empty() && token.size() <= 9 &&
      std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; });
  const int value = digits ? std::stoi(token) : 0;
  if (value <= 0) throw InputError(path, std::string("invalid PFM ") + what + " '" + token + "'");
  return value;
}

// ---- PNG through libpng (png_support.h) ----------------------------------------------------

struct PngWriteJob {
  std::FILE* file = nullptr;
  int width = 0, height = 0;
  png_bytep* rows = nullptr;  // height rows of width * 3 bytes, top row first
  png_textp text = nullptr;
  int text_count = 0;
  bool srgb = false;
  PngError error;
};

bool run_png_write(PngWriteJob& job) {
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &job.error, on_png_error, on_png_warning);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, job.file);
  png_set_IHDR(png, info, static_cast<png_uint_32>(job.width), static_cast<png_uint_32>(job.height),
               8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  // Tag sRGB-encoded images; the classic encoding stays untagged, as fixed-function OpenGL wrote.
  if (job.srgb) png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  if (job.text_count > 0) png_set_text(png, info, job.text, job.text_count);
  png_write_info(png, info);
  png_write_image(png, job.rows);
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

// 8-bit RGB output, whatever the file holds (the scene PNGs gloss writes and reads back).
void png_to_rgb8(PngReadJob& job) {
  const png_byte color_type = png_get_color_type(job.png, job.info);
  const png_byte bit_depth = png_get_bit_depth(job.png, job.info);
  if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(job.png);
  if (color_type == PNG_COLOR_TYPE_GRAY && bit_depth < 8) png_set_expand_gray_1_2_4_to_8(job.png);
  if (bit_depth == 16) png_set_scale_16(job.png);
  if ((color_type & PNG_COLOR_MASK_ALPHA) != 0) png_set_strip_alpha(job.png);
  if ((color_type & PNG_COLOR_MASK_COLOR) == 0) png_set_gray_to_rgb(job.png);
}

// PNG keywords: 1 to 79 printable Latin-1 characters, no leading, trailing or double spaces.
// gloss restricts them to printable ASCII.
bool is_valid_png_keyword(const std::string& keyword) {
  if (keyword.empty() || keyword.size() > 79) return false;
  if (keyword.front() == ' ' || keyword.back() == ' ') return false;
  if (keyword.find("  ") != std::string::npos) return false;
  return std::all_of(keyword.begin(), keyword.end(), [](char c) { return c >= 32 && c <= 126; });
}

bool is_ascii(const std::string& text) {
  return std::all_of(text.begin(), text.end(),
                     [](char c) { return static_cast<unsigned char>(c) < 128; });
}

// Above this many bytes a text chunk is stored compressed (zTXt, or compressed iTXt).
constexpr std::size_t compress_text_above = 1024;

// The libpng description of one text pair. ASCII text goes in tEXt/zTXt (Latin-1 by the PNG
// spec); anything else is taken as UTF-8 and goes in iTXt. Points into the strings of pair.
png_text describe_text_chunk(const std::pair<std::string, std::string>& pair) {
  png_text chunk{};
  const bool long_text = pair.second.size() > compress_text_above;
  if (is_ascii(pair.second)) {
    chunk.compression = long_text ? PNG_TEXT_COMPRESSION_zTXt : PNG_TEXT_COMPRESSION_NONE;
  } else {
    chunk.compression = long_text ? PNG_ITXT_COMPRESSION_zTXt : PNG_ITXT_COMPRESSION_NONE;
  }
  // libpng takes non-const pointers but does not write through them.
  chunk.key = const_cast<png_charp>(pair.first.c_str());
  chunk.text = const_cast<png_charp>(pair.second.c_str());
  chunk.text_length = pair.second.size();
  return chunk;
}

}  // namespace

unsigned char encode_channel(float linear, bool srgb) {
  DisplayTransform display;
  display.srgb = srgb;
  return display_byte(linear, display);
}

void write_pfm(const std::string& path, const Image& image) {
  check_image_shape(path, image);
  std::string bytes =
      "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
  bytes.reserve(bytes.size() + image.pixels.size() * 12);
  for (int y = image.height - 1; y >= 0; --y) {
    for (int x = 0; x < image.width; ++x) {
      const glm::vec3& p = image.at(x, y);
      append_float_le(bytes, p.x);
      append_float_le(bytes, p.y);
      append_float_le(bytes, p.z);
    }
  }
  write_text_atomically(path, bytes);
}

Image read_pfm(const std::string& path) {
  const std::string bytes = read_text_file(path);
  std::size_t pos = 0;
  const std::string magic = next_token(bytes, pos);
  if (magic != "PF" && magic != "Pf") throw InputError(path, "not a PFM file (no PF/Pf header)");
  const int channels = magic == "PF" ? 3 : 1;
  const int width = parse_dimension(path, next_token(bytes, pos), "width");
  const int height = parse_dimension(path, next_token(bytes, pos), "height");
  const std::string scale_token = next_token(bytes, pos);
  char* end = nullptr;
  const double scale = std::strtod(scale_token.c_str(), &end);
  if (scale_token.empty() || *end != '\0' || !std::isfinite(scale) || scale == 0.0) {
    throw InputError(path, "invalid PFM scale '" + scale_token + "'");
  }
  // Exactly one whitespace byte separates the header from the data.
  if (pos >= bytes.size() || !is_space(bytes[pos])) {
    throw InputError(path, "PFM header ends without pixel data");
  }
  ++pos;
  const bool little_endian = scale < 0;  // the PFM convention: the sign gives the byte order

  const std::uint64_t available = bytes.size() - pos;
  const std::uint64_t pixel_bytes = 4u * static_cast<std::uint64_t>(channels);
  const std::uint64_t pixel_count = static_cast<std::uint64_t>(width) * height;
  const std::string size_text = std::to_string(width) + "x" + std::to_string(height);
  if (pixel_count > available / pixel_bytes) {
    throw InputError(path, "PFM pixel data is truncated: " + std::to_string(available) +
                               " bytes for a " + size_text + " image");
  }
  if (pixel_count * pixel_bytes != available) {
    throw InputError(path, "PFM pixel data has " + std::to_string(available) + " bytes, expected " +
                               std::to_string(pixel_count * pixel_bytes) + " for a " + size_text +
                               " image");
  }

  Image image(width, height);
  for (int row = 0; row < height; ++row) {
    const int y = height - 1 - row;  // scanlines are stored bottom to top
    for (int x = 0; x < width; ++x) {
      const std::size_t at = pos + (static_cast<std::size_t>(row) * width + x) * pixel_bytes;
      glm::vec3& p = image.at(x, y);
      if (channels == 3) {
        p = glm::vec3(float_at(bytes, at, little_endian), float_at(bytes, at + 4, little_endian),
                      float_at(bytes, at + 8, little_endian));
      } else {
        p = glm::vec3(float_at(bytes, at, little_endian));
      }
    }
  }
  return image;
}

void write_png(const std::string& path, const Image& image, bool srgb, const TextChunks& text) {
  DisplayTransform display;
  display.srgb = srgb;
  write_png(path, image, display, text);
}

void write_png(const std::string& path, const Image& image, const DisplayTransform& display,
               const TextChunks& text) {
  check_image_shape(path, image);
  std::vector<png_text> chunks;
  for (const auto& pair : text) {
    if (!is_valid_png_keyword(pair.first)) {
      fail_write(path, "invalid PNG text keyword '" + pair.first + "'");
    }
    if (pair.second.find('\0') != std::string::npos) {
      fail_write(path, "PNG text '" + pair.first + "' contains a NUL byte");
    }
    chunks.push_back(describe_text_chunk(pair));
  }

  const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 3;
  std::vector<unsigned char> rgb = display_bytes(image, display);
  std::vector<png_bytep> rows(image.height);
  for (int y = 0; y < image.height; ++y) rows[y] = rgb.data() + row_bytes * y;

  write_stream_atomically(path, [&](std::FILE* file) {
    PngWriteJob job;
    job.file = file;
    job.width = image.width;
    job.height = image.height;
    job.rows = rows.data();
    job.text = chunks.data();
    job.text_count = static_cast<int>(chunks.size());
    job.srgb = display.srgb;
    errno = 0;
    if (run_png_write(job)) return;
    // A short fwrite is libpng's "Write Error"; the stream's errno says why (ENOSPC: disk full).
    if (std::ferror(file) != 0 && job.error.system_error != 0) {
      throw_write_error(path, job.error.system_error);
    }
    fail_write(path, job.error.message);
  });
}

Png8 read_png(const std::string& path) {
  // gloss writes no image larger than a render (scene/render_settings.h).
  PngFile file(path, kMaxImageSide, png_to_rgb8);
  PngReadJob& job = file.job();
  if (job.row_bytes != static_cast<std::size_t>(job.width) * 3) {
    throw InputError(path, "PNG does not decode to 8-bit RGB");
  }

  // The header's size is the file's word: refused before the pixels are allocated, with the
  // renderer's own pixel limit, so a 1000000x1000000 header is an InputError, not bad_alloc.
  const long long pixels = static_cast<long long>(job.width) * job.height;
  if (pixels > kMaxImagePixels) {
    throw InputError(path, "PNG is " + std::to_string(job.width) + "x" +
                               std::to_string(job.height) + ", more than the limit of " +
                               std::to_string(kMaxImagePixels) + " pixels");
  }
  Png8 png;
  png.width = job.width;
  png.height = job.height;
  png.rgb.resize(job.row_bytes * job.height);
  std::vector<png_bytep> rows(job.height);
  for (int y = 0; y < job.height; ++y) rows[y] = png.rgb.data() + job.row_bytes * y;
  file.read_rows(rows.data());

  png_textp text = nullptr;
  int text_count = 0;
  png_get_text(job.png, job.info, &text, &text_count);
  for (int i = 0; i < text_count; ++i) {
    const std::size_t length = text[i].compression >= PNG_ITXT_COMPRESSION_NONE
                                   ? text[i].itxt_length
                                   : text[i].text_length;
    png.text.emplace_back(text[i].key,
                          text[i].text != nullptr ? std::string(text[i].text, length) : "");
  }
  return png;
}

}  // namespace gloss

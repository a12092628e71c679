// read_png_image (map_readers.h): a PNG of any colour type and bit depth as linear floats,
// through libpng (png_support.h).
#include <cstdint>
#include <vector>

#include "base/error.h"
#include "io/image/map_readers.h"
#include "io/image/png_support.h"

namespace gloss {

namespace {

// Every colour type to 8- or 16-bit grey, grey and alpha, RGB or RGBA in the machine's order:
// palettes expanded (a tRNS chunk becomes alpha), low bit depths widened.
void png_to_samples(PngReadJob& job) {
  const png_byte color_type = png_get_color_type(job.png, job.info);
  const png_byte bit_depth = png_get_bit_depth(job.png, job.info);
  if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(job.png);
  if (color_type == PNG_COLOR_TYPE_GRAY && bit_depth < 8) png_set_expand_gray_1_2_4_to_8(job.png);
  if (png_get_valid(job.png, job.info, PNG_INFO_tRNS) != 0) png_set_tRNS_to_alpha(job.png);
  if (bit_depth == 16) {
    const std::uint16_t probe = 1;
    if (*reinterpret_cast<const unsigned char*>(&probe) == 1) png_set_swap(job.png);
  }
}

// Whether the file says its samples are linear: a gAMA chunk of 1.0 (stored as 100000) and no
// sRGB chunk. Anything else (no chunk, sRGB, another gamma, an ICC profile) is taken as sRGB,
// as docs/spec/shading.md asks of colour maps.
bool says_linear(PngReadJob& job) {
  if (png_get_valid(job.png, job.info, PNG_INFO_sRGB) != 0) return false;
  png_fixed_point gamma = 0;
  if (png_get_gAMA_fixed(job.png, job.info, &gamma) == 0) return false;
  return gamma >= 99000 && gamma <= 101000;
}

}  // namespace

FloatImage read_png_image(const std::string& path, const ImageReadOptions& options,
                          ImageFileInfo& info) {
  PngFile file(path, kMaxMapSide, png_to_samples);
  PngReadJob& job = file.job();
  const int channels = png_get_channels(job.png, job.info);
  const int depth = png_get_bit_depth(job.png, job.info);
  info.format = "PNG";
  info.bits = depth;
  if ((depth != 8 && depth != 16) || channels < 1 || channels > 4 ||
      job.row_bytes != static_cast<std::size_t>(job.width) * channels * (depth / 8)) {
    throw InputError(path, "PNG does not decode to 8- or 16-bit samples");
  }
  const std::uint64_t raw_bytes = static_cast<std::uint64_t>(job.row_bytes) * job.height;
  check_image_size(path, "PNG", job.width, job.height, channels, options, raw_bytes);

  std::vector<unsigned char> raw(raw_bytes);
  std::vector<png_bytep> rows(static_cast<std::size_t>(job.height));
  for (int y = 0; y < job.height; ++y) rows[y] = raw.data() + job.row_bytes * y;
  file.read_rows(rows.data());

  const bool decode = options.data == ImageData::colour && !says_linear(job);
  info.srgb_decoded = decode;
  const int alpha = channels == 2 || channels == 4 ? channels - 1 : -1;
  const double top = depth == 8 ? 255.0 : 65535.0;
  // One float per stored value, through the sRGB curve where it applies (a table: 256 or 65536
  // entries).
  std::vector<float> linear(static_cast<std::size_t>(top) + 1), plain(linear.size());
  for (std::size_t v = 0; v < linear.size(); ++v) {
    plain[v] = static_cast<float>(static_cast<double>(v) / top);
    linear[v] = decode ? srgb_to_linear(plain[v]) : plain[v];
  }
  FloatImage image;
  image.width = job.width;
  image.height = job.height;
  image.channels = channels;
  image.samples.resize(static_cast<std::size_t>(job.width) * job.height * channels);
  const std::size_t count = image.samples.size();
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t v =
        depth == 8 ? raw[i] : reinterpret_cast<const std::uint16_t*>(raw.data())[i];
    const bool is_alpha = alpha >= 0 && static_cast<int>(i % channels) == alpha;
    image.samples[i] = is_alpha ? plain[v] : linear[v];
  }
  return image;
}

}  // namespace gloss

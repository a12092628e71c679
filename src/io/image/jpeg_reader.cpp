// read_jpeg_image (map_readers.h): baseline and progressive JPEG through libjpeg-turbo
// (libjpeg-dev), grey or colour (CMYK and YCCK files come out as RGB), 8 bits per sample. A JPEG
// says nothing about its encoding, so colour maps take it as sRGB, as every painting tool writes
// it.
// Why libjpeg and not stb_image, which reads the HDR maps: Debian's libstb is built with its
// assertions on, and a corrupt progressive file whose Huffman tables are used before they are
// defined reads uninitialised memory and aborts in stbi__jpeg_huff_decode (fuzzing found it).
// libjpeg-turbo is the reference decoder, fuzzed by its maintainers; its errors come back here.
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <jpeglib.h>
// jerror.h after jpeglib.h: it names the message codes (JWRN_JPEG_EOF, JERR_NO_BACKING_STORE, ...).
#include <jerror.h>

#include "base/error.h"
#include "io/image/map_readers.h"
#include "io/image/stb_memory.h"  // read_file_bytes

namespace gloss {
namespace {

// libjpeg reports a fatal error by calling error_exit, which must not return: it jumps back to
// the setjmp in run_stage with the message kept. A warning that the data ended early (libjpeg
// then fills the rest of the image with grey) is kept as truncation; other warnings (extra bytes
// between markers, a corrupt restart interval) leave an image worth showing and are ignored, as
// every viewer does.
struct JpegErrors {
  jpeg_error_mgr base;
  std::jmp_buf escape;
  char message[JMSG_LENGTH_MAX] = {};
  bool truncated = false;
};

void on_error(j_common_ptr cinfo) {
  JpegErrors* errors = reinterpret_cast<JpegErrors*>(cinfo->err);
  (*cinfo->err->format_message)(cinfo, errors->message);
  std::longjmp(errors->escape, 1);
}

void on_message(j_common_ptr cinfo, int level) {
  JpegErrors* errors = reinterpret_cast<JpegErrors*>(cinfo->err);
  if (level < 0 && cinfo->err->msg_code == JWRN_JPEG_EOF) errors->truncated = true;
}

// One decompression: the libjpeg state and where the pixels go. Owned by read_jpeg_image's frame,
// so the setjmp in run_stage skips no destructor when libjpeg jumps back.
struct Decoder {
  jpeg_decompress_struct cinfo{};
  JpegErrors errors{};
  std::vector<unsigned char> pixels;  // row-major, out_color_components per pixel
  bool created = false;

  Decoder() {
    cinfo.err = jpeg_std_error(&errors.base);
    errors.base.error_exit = on_error;
    errors.base.emit_message = on_message;
  }
  ~Decoder() {
    if (created) jpeg_destroy_decompress(&cinfo);
  }
};

void read_header(Decoder& d, const std::vector<unsigned char>& bytes) {
  // Created first: a failed create (out of memory) has set cinfo.mem or left it null, and
  // jpeg_destroy_decompress frees what there is either way.
  d.created = true;
  jpeg_create_decompress(&d.cinfo);
  jpeg_mem_src(&d.cinfo, bytes.data(), static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(&d.cinfo, TRUE);
  // Adobe CMYK and YCCK come out as CMYK (inverted, as Adobe writes them); grey stays grey and
  // everything else becomes RGB.
  const J_COLOR_SPACE in = d.cinfo.jpeg_color_space;
  d.cinfo.out_color_space = in == JCS_GRAYSCALE                  ? JCS_GRAYSCALE
                            : (in == JCS_CMYK || in == JCS_YCCK) ? JCS_CMYK
                                                                 : JCS_RGB;
  jpeg_calc_output_dimensions(&d.cinfo);
}

void decode_pixels(Decoder& d) {
  jpeg_start_decompress(&d.cinfo);
  const std::size_t row = std::size_t(d.cinfo.output_width) * d.cinfo.output_components;
  d.pixels.resize(row * d.cinfo.output_height);
  while (d.cinfo.output_scanline < d.cinfo.output_height) {
    JSAMPROW at = d.pixels.data() + row * d.cinfo.output_scanline;
    jpeg_read_scanlines(&d.cinfo, &at, 1);
  }
  jpeg_finish_decompress(&d.cinfo);
}

// Runs one stage under libjpeg's error handler; false (message in d.errors) when libjpeg gave up.
// No object with a destructor lives in this frame, so the jump back is well defined.
template <class Stage>
bool run_stage(Decoder& d, Stage stage) {
  if (setjmp(d.errors.escape) != 0) return false;
  stage();
  return true;
}

}  // namespace

FloatImage read_jpeg_image(const std::string& path, const ImageReadOptions& options,
                           ImageFileInfo& info) {
  info.format = "JPEG";
  info.bits = 8;
  // The file is decoded from memory: its bytes count against the budget with the floats.
  const std::vector<unsigned char> bytes = read_file_bytes(path, "JPEG", options);
  Decoder d;
  if (!run_stage(d, [&] { read_header(d, bytes); })) {
    throw InputError(path, std::string("invalid JPEG: ") + d.errors.message);
  }
  const int stored = d.cinfo.output_components;  // 1, 3 or 4 (CMYK)
  const int channels = stored == 4 ? 3 : stored;
  const long long width = d.cinfo.output_width, height = d.cinfo.output_height;
  const std::uint64_t ours = bytes.size() + std::uint64_t(width) * height * stored;
  check_image_size(path, "JPEG", width, height, channels, options, ours);
  // What libjpeg allocates besides: a progressive file keeps every DCT coefficient of the image
  // (128 bytes per 8x8 block and component) until the last scan. It has no backing store, so past
  // this limit it gives up (JERR_NO_BACKING_STORE) instead of allocating.
  const std::uint64_t floats = std::uint64_t(width) * height * channels * sizeof(float);
  const std::uint64_t budget = image_budget(options);
  d.cinfo.mem->max_memory_to_use =
      static_cast<long>(budget > ours + floats + 1 ? budget - ours - floats : 1);  // 0: no limit
  if (!run_stage(d, [&] { decode_pixels(d); })) {
    // Past max_memory_to_use libjpeg wants a backing store; an allocation it cannot make at
    // all is JERR_OUT_OF_MEMORY. Both mean the budget.
    const int code = d.errors.base.msg_code;
    if (code == JERR_NO_BACKING_STORE || code == JERR_OUT_OF_MEMORY) {
      throw InputError(path, "JPEG of " + std::to_string(width) + "x" + std::to_string(height) +
                                 " pixels needs more than the memory budget of " +
                                 std::to_string(budget >> 20) + " MB to decode");
    }
    throw InputError(path, std::string("invalid JPEG: ") + d.errors.message);
  }
  if (d.errors.truncated) {
    throw InputError(path, "invalid JPEG: the image data is truncated (" +
                               std::to_string(bytes.size()) + " bytes)");
  }
  const bool decode = options.data == ImageData::colour;
  info.srgb_decoded = decode;
  float table[256];
  for (int v = 0; v < 256; ++v) {
    const float plain = static_cast<float>(v / 255.0);
    table[v] = decode ? srgb_to_linear(plain) : plain;
  }
  FloatImage image;
  image.width = static_cast<int>(width);
  image.height = static_cast<int>(height);
  image.channels = channels;
  image.samples.resize(static_cast<std::size_t>(width) * height * channels);
  const unsigned char* in = d.pixels.data();
  if (stored == 4) {
    // CMYK as Adobe stores it (each ink inverted): the colour is ink times key, k*c/255 rounded,
    // the conversion stb_image and browsers use.
    for (std::size_t p = 0; p < std::size_t(width) * height; ++p, in += 4) {
      for (int c = 0; c < 3; ++c) {
        const unsigned rgb = (unsigned(in[c]) * in[3] + 127u) / 255u;
        image.samples[p * 3 + c] = table[rgb];
      }
    }
  } else {
    for (std::size_t i = 0; i < image.samples.size(); ++i) image.samples[i] = table[in[i]];
  }
  return image;
}

}  // namespace gloss

// Map images (io/image/image_reader.h): PNG of every colour type and bit depth, Radiance HDR and
// OpenEXR (float, half, DWAB) read into linear floats with the values worked out by hand, and
// every kind of bad file refused in one line naming it: missing, not an image, corrupt,
// truncated, NaN-filled, larger than the map limit or than the memory budget.
#include "io/image/image_reader.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <zlib.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "base/error.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

// ---- a minimal PNG writer (signature, chunks with their CRC, one zlib IDAT, no filtering) ----

void put32(std::string& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<char>((v >> s) & 0xff));
}

void chunk(std::string& out, const char* type, const std::string& data) {
  put32(out, static_cast<std::uint32_t>(data.size()));
  const std::string body = std::string(type, 4) + data;
  out += body;
  put32(out, static_cast<std::uint32_t>(
                 crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()))));
}

// rows: height rows of packed samples (without the filter byte).
std::string png_bytes(int width, int height, int depth, int colour_type,
                      const std::vector<std::string>& rows, const std::string& extra_chunks = "") {
  std::string out("\x89PNG\r\n\x1a\n", 8);
  std::string ihdr;
  put32(ihdr, static_cast<std::uint32_t>(width));
  put32(ihdr, static_cast<std::uint32_t>(height));
  ihdr += {static_cast<char>(depth), static_cast<char>(colour_type), 0, 0, 0};
  chunk(out, "IHDR", ihdr);
  out += extra_chunks;
  std::string raw;
  for (const std::string& row : rows) raw += '\0' + row;
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::string packed(size, '\0');
  compress(reinterpret_cast<Bytef*>(&packed[0]), &size, reinterpret_cast<const Bytef*>(raw.data()),
           static_cast<uLong>(raw.size()));
  packed.resize(size);
  chunk(out, "IDAT", packed);
  chunk(out, "IEND", "");
  return out;
}

std::string write(const ScratchFolder& folder, const std::string& name, const std::string& bytes) {
  const std::string path = folder.file(name);
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

double srgb(double v) {  // the sRGB curve's inverse, by hand
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

std::string error_of(const std::string& path, const ImageReadOptions& options = {}) {
  try {
    read_image(path, options);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted " << path;
  return "";
}

TEST(ImageReader, PngOfEveryColourTypeAndDepth) {
  ScratchFolder folder;
  // 8-bit RGB: sRGB-decoded.
  FloatImage rgb = read_image(write(folder, "rgb8.png", png_bytes(2, 1, 8, 2, {std::string("\xbc\x00\xff\x40\x80\x20", 6)})));
  ASSERT_EQ(rgb.channels, 3);
  EXPECT_NEAR(rgb.at(0, 0, 0), srgb(188 / 255.0), 1e-6);
  EXPECT_EQ(rgb.at(0, 0, 1), 0.0f);
  EXPECT_NEAR(rgb.at(0, 0, 2), 1.0, 1e-6);
  EXPECT_NEAR(rgb.at(1, 0, 1), srgb(128 / 255.0), 1e-6);
  // The same as data: byte / 255.
  ImageReadOptions data;
  data.data = ImageData::linear;
  EXPECT_NEAR(read_image(folder.file("rgb8.png"), data).at(0, 0, 0), 188 / 255.0, 1e-7);
  // A gAMA of 1.0 (100000) says linear.
  std::string gamma;
  put32(gamma, 100000);
  std::string linear_chunks;
  chunk(linear_chunks, "gAMA", gamma);
  const FloatImage linear = read_image(
      write(folder, "linear.png", png_bytes(1, 1, 8, 2, {"\xbc\x10\x20"}, linear_chunks)));
  EXPECT_NEAR(linear.at(0, 0, 0), 188 / 255.0, 1e-7);
  // 16-bit RGBA: words / 65535, alpha never decoded.
  const FloatImage rgba16 = read_image(write(
      folder, "rgba16.png", png_bytes(1, 1, 16, 6, {std::string("\xff\xff\x80\x00\x00\x00\x40\x00", 8)})));
  ASSERT_EQ(rgba16.channels, 4);
  EXPECT_NEAR(rgba16.at(0, 0, 0), 1.0, 1e-7);
  EXPECT_NEAR(rgba16.at(0, 0, 1), srgb(32768 / 65535.0), 1e-6);
  EXPECT_NEAR(rgba16.at(0, 0, 3), 16384 / 65535.0, 1e-7);
  // 1-bit grey: 0 and 1.
  const FloatImage bits = read_image(write(folder, "grey1.png", png_bytes(8, 1, 1, 0, {"\xa0"})));
  ASSERT_EQ(bits.channels, 1);
  EXPECT_EQ(bits.at(0, 0, 0), 1.0f);
  EXPECT_EQ(bits.at(1, 0, 0), 0.0f);
  EXPECT_EQ(bits.at(2, 0, 0), 1.0f);
  // 8-bit grey and alpha.
  const FloatImage ga = read_image(write(folder, "ga8.png", png_bytes(1, 1, 8, 4, {"\xff\x80"})));
  ASSERT_EQ(ga.channels, 2);
  EXPECT_NEAR(ga.at(0, 0, 1), 128 / 255.0, 1e-7);
  // A palette with transparency: RGBA.
  std::string palette_chunks;
  chunk(palette_chunks, "PLTE", std::string("\x00\x00\x00\xff\x00\x00", 6));
  chunk(palette_chunks, "tRNS", std::string("\xff\x00", 2));
  const FloatImage palette = read_image(
      write(folder, "palette.png", png_bytes(2, 1, 8, 3, {std::string("\x00\x01", 2)}, palette_chunks)));
  ASSERT_EQ(palette.channels, 4);
  EXPECT_EQ(palette.at(1, 0, 0), 1.0f);
  EXPECT_EQ(palette.at(1, 0, 3), 0.0f);
  EXPECT_EQ(palette.at(0, 0, 3), 1.0f);
}

TEST(ImageReader, RadianceHdr) {
  ScratchFolder folder;
  // Flat RGBE: (128, 64, 32, 129) is 128 * 2^(129 - 136) = 1, 0.5, 0.25.
  const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n";
  const std::string pixels("\x80\x40\x20\x81\x80\x80\x80\x80", 8);
  const FloatImage hdr = read_image(write(folder, "a.hdr", header + pixels));
  ASSERT_EQ(hdr.channels, 3);
  EXPECT_NEAR(hdr.at(0, 0, 0), 1.0, 1e-7);
  EXPECT_NEAR(hdr.at(0, 0, 1), 0.5, 1e-7);
  EXPECT_NEAR(hdr.at(0, 0, 2), 0.25, 1e-7);
  EXPECT_NEAR(hdr.at(1, 0, 0), 0.5, 1e-7);
  // Cut short: refused, not read as black.
  const std::string cut = error_of(write(folder, "cut.hdr", header + pixels.substr(0, 5)));
  EXPECT_NE(cut.find("truncated"), std::string::npos) << cut;
}

std::string write_exr(const ScratchFolder& folder, const std::string& name, int w, int h,
                      Imf::PixelType type, Imf::Compression compression,
                      const std::vector<float>& rgb) {
  const std::string path = folder.file(name);
  Imf::Header header(w, h);
  header.compression() = compression;
  for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(type));
  Imf::OutputFile file(path.c_str(), header);
  Imf::FrameBuffer frame;
  std::vector<half> halves(rgb.begin(), rgb.end());
  for (int c = 0; c < 3; ++c) {
    const char* name_c = c == 0 ? "R" : c == 1 ? "G" : "B";
    if (type == Imf::FLOAT) {
      frame.insert(name_c, Imf::Slice(Imf::FLOAT, (char*)(rgb.data() + c), 12, 12 * w));
    } else {
      frame.insert(name_c, Imf::Slice(Imf::HALF, (char*)(halves.data() + c), 6, 6 * w));
    }
  }
  file.setFrameBuffer(frame);
  file.writePixels(h);
  return path;
}

TEST(ImageReader, OpenExrFloatHalfAndDwab) {
  ScratchFolder folder;
  std::vector<float> rgb(4 * 2 * 3);
  for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = 0.25f * static_cast<float>(i);
  rgb[5] = 1e6f;  // a sun
  const FloatImage f = read_image(write_exr(folder, "f.exr", 4, 2, Imf::FLOAT, Imf::ZIP_COMPRESSION, rgb));
  ASSERT_EQ(f.channels, 3);
  ASSERT_EQ(f.width, 4);
  for (std::size_t i = 0; i < rgb.size(); ++i) EXPECT_EQ(f.samples[i], rgb[i]) << i;
  rgb[5] = 1000.0f;  // half holds up to 65504
  const FloatImage h = read_image(write_exr(folder, "h.exr", 4, 2, Imf::HALF, Imf::PIZ_COMPRESSION, rgb));
  for (std::size_t i = 0; i < rgb.size(); ++i) EXPECT_EQ(h.samples[i], float(half(rgb[i]))) << i;
  // DWAB (lossy): near the values.
  std::vector<float> smooth(64 * 32 * 3);
  for (std::size_t i = 0; i < smooth.size(); ++i) smooth[i] = 0.5f + 0.001f * static_cast<float>(i % 97);
  const FloatImage d = read_image(write_exr(folder, "d.exr", 64, 32, Imf::FLOAT, Imf::DWAB_COMPRESSION, smooth));
  for (std::size_t i = 0; i < smooth.size(); ++i) EXPECT_NEAR(d.samples[i], smooth[i], 0.02) << i;
  // NaN: refused, naming the pixel.
  std::vector<float> bad(rgb);
  bad[7] = std::numeric_limits<float>::quiet_NaN();
  const std::string nan = error_of(write_exr(folder, "nan.exr", 4, 2, Imf::FLOAT, Imf::ZIP_COMPRESSION, bad));
  EXPECT_NE(nan.find("pixel (2, 0) holds NaN"), std::string::npos) << nan;
  // Truncated.
  std::ifstream whole(folder.file("d.exr"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(whole)), {});
  const std::string cut = error_of(write(folder, "cut.exr", bytes.substr(0, bytes.size() / 2)));
  EXPECT_NE(cut.find("invalid OpenEXR"), std::string::npos) << cut;
  EXPECT_NE(cut.find("cut.exr"), std::string::npos) << cut;
}

TEST(ImageReader, BadFilesAreOneLineErrorsNamingTheFile) {
  ScratchFolder folder;
  EXPECT_NE(error_of(folder.file("missing.exr")).find("missing.exr: cannot read"), std::string::npos);
  EXPECT_NE(error_of(write(folder, "text.png", "hello")).find("not an image"), std::string::npos);
  std::string corrupt = png_bytes(2, 2, 8, 2, {"abcdef", "ghijkl"});
  corrupt[corrupt.size() - 20] ^= 0x55;  // inside IDAT: a CRC (or inflate) error
  EXPECT_NE(error_of(write(folder, "corrupt.png", corrupt)).find("invalid PNG"), std::string::npos);
  // Larger than any map may be.
  const std::string huge = error_of(write(folder, "huge.png", png_bytes(40000, 1, 8, 0, {std::string(40000, '\0')})));
  EXPECT_NE(huge.find("huge.png"), std::string::npos) << huge;
  // 16384 x 16384 grey (33 KB of PNG) against a 64 MB budget: refused before its 1 GB of floats.
  std::vector<std::string> rows(16384, std::string(16384 / 8, '\0'));
  const std::string big = write(folder, "big.png", png_bytes(16384, 16384, 1, 0, rows));
  ImageReadOptions small;
  small.budget_bytes = std::uint64_t(64) << 20;
  const std::string budget = error_of(big, small);
  // 1024 MB of floats and the 256 MB of 8-bit samples libpng expands the bits to.
  EXPECT_NE(budget.find("16384x16384 pixels needs ~1280 MB, more than the memory budget of 64 MB"),
            std::string::npos)
      << budget;
  for (const char* line : {huge.c_str(), budget.c_str()}) {
    EXPECT_EQ(std::string(line).find('\n'), std::string::npos);
  }
}

}  // namespace
}  // namespace gloss

// Map images (io/image/image_reader.h): PNG of every colour type and bit depth, Radiance HDR and
// OpenEXR (float, half, DWAB) read into linear floats with the values worked out by hand, and
// every kind of bad file refused in one line naming it: missing, not an image, corrupt,
// truncated, NaN-filled, larger than the map limit or than the memory budget, and the headers
// the fuzzers found that made a library allocate gigabytes or loop forever.
#include "io/image/image_reader.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfPartType.h>
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
  put32(out, static_cast<std::uint32_t>(crc32(0, reinterpret_cast<const Bytef*>(body.data()),
                                              static_cast<uInt>(body.size()))));
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
  FloatImage rgb = read_image(write(
      folder, "rgb8.png", png_bytes(2, 1, 8, 2, {std::string("\xbc\x00\xff\x40\x80\x20", 6)})));
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
  const FloatImage rgba16 = read_image(
      write(folder, "rgba16.png",
            png_bytes(1, 1, 16, 6, {std::string("\xff\xff\x80\x00\x00\x00\x40\x00", 8)})));
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
  const FloatImage palette = read_image(write(
      folder, "palette.png", png_bytes(2, 1, 8, 3, {std::string("\x00\x01", 2)}, palette_chunks)));
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

// Run-length scan lines (widths 8 to 32767): 2, 2, the width in 2 bytes, then each of R, G, B, E
// as runs (128 + count, value) and dumps (count, bytes). stb_image loops forever on a line cut
// short or on a dump of 0 bytes: without gloss's own walk of the data these tests never end.
TEST(ImageReader, RadianceHdrScanLinesCutShortOrEndlessAreRefused) {
  ScratchFolder folder;
  const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 8\n";
  // Line 0: 8 pixels of (128, 64, 32, 129) = (1, 0.5, 0.25) as four runs; line 1: R as a dump of
  // 8 bytes (128 = 1.0 ... 135 = 135/128), G, B, E as runs.
  const std::string line0("\x02\x02\x00\x08\x88\x80\x88\x40\x88\x20\x88\x81", 12);
  const std::string line1 = std::string("\x02\x02\x00\x08\x08", 5) +
                            "\x80\x81\x82\x83\x84\x85\x86\x87" +
                            std::string("\x88\x40\x88\x20\x88\x81", 6);
  const FloatImage whole = read_image(write(folder, "rle.hdr", header + line0 + line1));
  ASSERT_EQ(whole.width, 8);
  EXPECT_NEAR(whole.at(7, 0, 0), 1.0, 1e-7);
  EXPECT_NEAR(whole.at(3, 0, 2), 0.25, 1e-7);
  EXPECT_NEAR(whole.at(5, 1, 0), 133 / 128.0, 1e-7);
  EXPECT_NEAR(whole.at(5, 1, 1), 0.5, 1e-7);
  // Line 1 ends inside its R dump.
  const std::string cut = error_of(write(folder, "cut.hdr", header + line0 + line1.substr(0, 9)));
  EXPECT_NE(
      cut.find("cut.hdr: invalid Radiance HDR: the pixel data is truncated (scan line 1 of 2"),
      std::string::npos)
      << cut;
  // A dump of 0 bytes where line 1's R starts: the data does not run out, stb just stops moving.
  std::string zero = line1;
  zero[4] = '\0';
  const std::string endless = error_of(write(folder, "zero.hdr", header + line0 + zero));
  EXPECT_NE(endless.find("scan line 1, channel 0, byte " + std::to_string(header.size() + 16) +
                         ": a dump of 0 bytes"),
            std::string::npos)
      << endless;
  // 4096 x 4096 (192 MB of floats, inside the budget) from one run of 127 pixels: refused before
  // stb allocates anything.
  const std::string big = error_of(write(folder, "big.hdr",
                                         "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4096 +X 4096\n" +
                                             std::string("\x02\x02\x10\x00\xff\x80", 6)));
  EXPECT_NE(big.find("truncated (scan line 0 of 4096"), std::string::npos) << big;
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
  const FloatImage f =
      read_image(write_exr(folder, "f.exr", 4, 2, Imf::FLOAT, Imf::ZIP_COMPRESSION, rgb));
  ASSERT_EQ(f.channels, 3);
  ASSERT_EQ(f.width, 4);
  for (std::size_t i = 0; i < rgb.size(); ++i) EXPECT_EQ(f.samples[i], rgb[i]) << i;
  rgb[5] = 1000.0f;  // half holds up to 65504
  const FloatImage h =
      read_image(write_exr(folder, "h.exr", 4, 2, Imf::HALF, Imf::PIZ_COMPRESSION, rgb));
  for (std::size_t i = 0; i < rgb.size(); ++i) EXPECT_EQ(h.samples[i], float(half(rgb[i]))) << i;
  // DWAB (lossy): near the values.
  std::vector<float> smooth(64 * 32 * 3);
  for (std::size_t i = 0; i < smooth.size(); ++i)
    smooth[i] = 0.5f + 0.001f * static_cast<float>(i % 97);
  const FloatImage d =
      read_image(write_exr(folder, "d.exr", 64, 32, Imf::FLOAT, Imf::DWAB_COMPRESSION, smooth));
  for (std::size_t i = 0; i < smooth.size(); ++i) EXPECT_NEAR(d.samples[i], smooth[i], 0.02) << i;
  // NaN: refused, naming the pixel.
  std::vector<float> bad(rgb);
  bad[7] = std::numeric_limits<float>::quiet_NaN();
  const std::string nan =
      error_of(write_exr(folder, "nan.exr", 4, 2, Imf::FLOAT, Imf::ZIP_COMPRESSION, bad));
  EXPECT_NE(nan.find("pixel (2, 0) holds NaN"), std::string::npos) << nan;
  // Truncated.
  std::ifstream whole(folder.file("d.exr"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(whole)), {});
  const std::string cut = error_of(write(folder, "cut.exr", bytes.substr(0, bytes.size() / 2)));
  EXPECT_NE(cut.find("invalid OpenEXR"), std::string::npos) << cut;
  EXPECT_NE(cut.find("cut.exr"), std::string::npos) << cut;
}

// ---- OpenEXR headers by hand (openexr.com, "OpenEXR File Layout"): the magic number, the version
// field (2, flags above), attributes as name\0 type\0 int32 size and the value, an empty name ----

std::string le32(long long v) {
  std::string out;
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
  return out;
}

std::string exr_start(int flags = 0) {
  return std::string("\x76\x2f\x31\x01", 4) + le32(2 | flags);
}

std::string attribute(const std::string& name, const std::string& type, const std::string& value,
                      long long declared) {
  return name + '\0' + type + '\0' + le32(declared) + value;
}
std::string attribute(const std::string& name, const std::string& type, const std::string& value) {
  return attribute(name, type, value, static_cast<long long>(value.size()));
}

// A header's size attributes: R, G, B and the extra channels (all HALF), the compression, the
// data window 0..w-1 x 0..h-1.
std::string size_attributes(int w, int h, int compression, int extra_channels = 0) {
  std::string list;
  std::vector<std::string> names = {"B", "G", "R"};
  for (int i = 0; i < extra_channels; ++i) names.push_back("X" + std::to_string(i));
  for (const std::string& n : names)
    list += n + '\0' + le32(1) + std::string(4, '\0') + le32(1) + le32(1);
  return attribute("channels", "chlist", list + '\0') +
         attribute("compression", "compression", std::string(1, static_cast<char>(compression))) +
         attribute("dataWindow", "box2i", le32(0) + le32(0) + le32(w - 1) + le32(h - 1));
}

TEST(ImageReader, OpenExrHeadersDeclaringMoreThanTheFileAreRefusedBeforeOpenExrReadsThem) {
  ScratchFolder folder;
  // OpenEXR allocates an attribute of a type it does not know at its declared size before it
  // reads a byte of it: here 2 GB for a 40-byte file (the fuzzer's 114 findings).
  const std::string huge = error_of(
      write(folder, "huge.exr", exr_start() + attribute("notes", "blob", "abc", 0x7fffff00)));
  EXPECT_NE(huge.find("huge.exr: invalid OpenEXR: attribute 'notes' (blob) declares 2147483392 "
                      "bytes, more than the 3 left in the file"),
            std::string::npos)
      << huge;
  const std::string negative =
      error_of(write(folder, "negative.exr", exr_start() + attribute("notes", "blob", "abc", -5)));
  EXPECT_NE(negative.find("attribute 'notes' (blob) declares a negative size (-5)"),
            std::string::npos)
      << negative;
  // A known type is read at its own size, whatever the file declares.
  const std::string box = error_of(write(
      folder, "box.exr", exr_start() + attribute("dataWindow", "box2i", std::string(20, '\0'))));
  EXPECT_NE(box.find("attribute 'dataWindow' (box2i) declares 20 bytes; a box2i is 16"),
            std::string::npos)
      << box;
  // No empty name before the end.
  const std::string open =
      error_of(write(folder, "open.exr", exr_start() + size_attributes(4, 2, 0)));
  EXPECT_NE(open.find("open.exr: invalid OpenEXR: the header does not end"), std::string::npos)
      << open;
  // Tiles of 1 x 1 on 4096 x 4096: a table of 16777216 chunks (128 MB) the 8-byte rest of the
  // file cannot hold.
  const std::string tiles =
      error_of(write(folder, "tiles.exr",
                     exr_start(0x200) + size_attributes(4096, 4096, 0) +
                         attribute("tiles", "tiledesc", le32(1) + le32(1) + std::string(1, '\0')) +
                         '\0' + std::string(8, '\0')));
  EXPECT_NE(tiles.find("ends inside its chunk offset tables (16777216 chunks"), std::string::npos)
      << tiles;
  // Two parts, the second declaring 100000000 chunks.
  const std::string part =
      attribute("name", "string", "a") + attribute("type", "string", "scanlineimage");
  const std::string parts = error_of(write(
      folder, "parts.exr",
      exr_start(0x1000) + size_attributes(4, 1, 0) + part +
          attribute("chunkCount", "int", le32(1)) + '\0' + size_attributes(4, 1, 0) +
          attribute("name", "string", "b") + attribute("type", "string", "scanlineimage") +
          attribute("chunkCount", "int", le32(100000000)) + '\0' + '\0' + std::string(16, '\0')));
  EXPECT_NE(parts.find("(100000001 chunks"), std::string::npos) << parts;
  // Types the library reads by their content, whatever size is declared (fuzz_exr's OOM
  // findings: a chlist under another name, read past its declared size, left OpenEXR reading the
  // next attribute's size from elsewhere: 1.8 GB). A chlist under any name, a preview whose
  // numbers claim 65535 x 65535 RGBA (8 + 65535 * 65535 * 4 = 17179344908 bytes) in 8 bytes, a
  // stringvector holding a 2 GB string in 8 bytes.
  const std::string list =
      error_of(write(folder, "list.exr", exr_start() + attribute("aspect", "chlist", "R") + '\0'));
  EXPECT_NE(list.find("attribute 'aspect' (chlist) ends inside a channel name"), std::string::npos)
      << list;
  const std::string preview = error_of(
      write(folder, "preview.exr",
            exr_start() + attribute("preview", "preview", le32(65535) + le32(65535)) + '\0'));
  EXPECT_NE(preview.find("attribute 'preview' (preview) of 65535x65535 needs 17179344908 bytes; "
                         "it declares 8"),
            std::string::npos)
      << preview;
  const std::string strings = error_of(
      write(folder, "strings.exr",
            exr_start() + attribute("views", "stringvector", le32(0x7fffffff) + "abcd") + '\0'));
  EXPECT_NE(strings.find("attribute 'views' (stringvector) holds a string of 2147483647 bytes, "
                         "more than 4 left in its value"),
            std::string::npos)
      << strings;
  for (const std::string& line :
       {huge, negative, box, open, tiles, parts, list, preview, strings}) {
    EXPECT_EQ(line.find('\n'), std::string::npos) << line;
  }
}

TEST(ImageReader, OpenExrBuffersCountAgainstTheBudgetBeforeOpenExrAllocatesThem) {
  ScratchFolder folder;
  // DWAB decodes 256 scan lines at a time: 32768 pixels x 16 HALF channels x 256 lines is 256 MB
  // per buffer, 4 of them (the chunk and the decompressor's copies) 1024 MB, with 0.4 MB of
  // floats for the map, against a 256 MB budget. Its one chunk's offset follows the header.
  const std::string path =
      write(folder, "wide.exr",
            exr_start() + size_attributes(32768, 1, 9, 13) + '\0' + le32(0) + le32(0));
  ImageReadOptions options;
  options.budget_bytes = std::uint64_t(256) << 20;
  const std::string wide = error_of(path, options);
  EXPECT_NE(wide.find("wide.exr: OpenEXR image of 32768x1 pixels needs ~1025 MB, more than the "
                      "memory budget of 256 MB"),
            std::string::npos)
      << wide;
}

TEST(ImageReader, OpenExrMultiPartReadsTheFirstPart) {
  ScratchFolder folder;
  const std::string path = folder.file("parts.exr");
  std::vector<float> rgb(4 * 2 * 3), grey(4 * 2, 7.0f);
  for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = 0.5f * static_cast<float>(i);
  {
    std::vector<Imf::Header> headers(2, Imf::Header(4, 2));
    headers[0].setName("colour");
    headers[1].setName("grey");
    for (const char* c : {"R", "G", "B"}) headers[0].channels().insert(c, Imf::Channel(Imf::FLOAT));
    headers[1].channels().insert("Y", Imf::Channel(Imf::FLOAT));
    for (Imf::Header& h : headers) h.setType(Imf::SCANLINEIMAGE);
    Imf::MultiPartOutputFile file(path.c_str(), headers.data(), 2);
    Imf::FrameBuffer colour, luminance;
    for (int c = 0; c < 3; ++c) {
      colour.insert(c == 0   ? "R"
                    : c == 1 ? "G"
                             : "B",
                    Imf::Slice(Imf::FLOAT, (char*)(rgb.data() + c), 12, 48));
    }
    luminance.insert("Y", Imf::Slice(Imf::FLOAT, (char*)grey.data(), 4, 16));
    Imf::OutputPart first(file, 0), second(file, 1);
    first.setFrameBuffer(colour);
    first.writePixels(2);
    second.setFrameBuffer(luminance);
    second.writePixels(2);
  }
  const FloatImage image = read_image(path);
  ASSERT_EQ(image.channels, 3);
  ASSERT_EQ(image.width, 4);
  for (std::size_t i = 0; i < rgb.size(); ++i) EXPECT_EQ(image.samples[i], rgb[i]) << i;
}

TEST(ImageReader, BadFilesAreOneLineErrorsNamingTheFile) {
  ScratchFolder folder;
  EXPECT_NE(error_of(folder.file("missing.exr")).find("missing.exr: cannot read"),
            std::string::npos);
  EXPECT_NE(error_of(write(folder, "text.png", "hello")).find("not an image"), std::string::npos);
  std::string corrupt = png_bytes(2, 2, 8, 2, {"abcdef", "ghijkl"});
  corrupt[corrupt.size() - 20] ^= 0x55;  // inside IDAT: a CRC (or inflate) error
  EXPECT_NE(error_of(write(folder, "corrupt.png", corrupt)).find("invalid PNG"), std::string::npos);
  // Larger than any map may be.
  const std::string huge =
      error_of(write(folder, "huge.png", png_bytes(40000, 1, 8, 0, {std::string(40000, '\0')})));
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

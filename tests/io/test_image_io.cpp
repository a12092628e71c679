#include "io/image/image_io.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>

#include "base/error.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// Decodes 4 little-endian bytes as an IEEE float, independently of the code under test.
float little_endian_float(const std::string& bytes, std::size_t at) {
  std::uint32_t bits = 0;
  for (int i = 0; i < 4; ++i) {
    bits |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  }
  float value = 0;
  std::memcpy(&value, &bits, 4);
  return value;
}

std::string big_endian_bytes(float value) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, 4);
  std::string out;
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>(bits >> shift));
  return out;
}

bool same_bits(float a, float b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(ImageIo, ClassicEncodingClampsAndRoundsToNearest) {
  EXPECT_EQ(encode_channel(0.5f, false), 128);   // 127.5 rounds up
  EXPECT_EQ(encode_channel(0.25f, false), 64);   // 63.75
  EXPECT_EQ(encode_channel(0.75f, false), 191);  // 191.25
  EXPECT_EQ(encode_channel(0.0f, false), 0);
  EXPECT_EQ(encode_channel(1.0f, false), 255);
  EXPECT_EQ(encode_channel(1.7f, false), 255);
  EXPECT_EQ(encode_channel(-1.0f, false), 0);
  EXPECT_EQ(encode_channel(std::numeric_limits<float>::quiet_NaN(), false), 0);
  EXPECT_EQ(encode_channel(std::numeric_limits<float>::infinity(), false), 255);
  EXPECT_EQ(encode_channel(-std::numeric_limits<float>::infinity(), false), 0);
}

TEST(ImageIo, SrgbEncodingFollowsTheStandardCurve) {
  // Evaluated in double by hand: 1.055 x^(1/2.4) - 0.055 above 0.0031308, 12.92 x below.
  EXPECT_EQ(encode_channel(0.5f, true), 188);   // 187.516
  EXPECT_EQ(encode_channel(0.2f, true), 124);   // 123.555
  EXPECT_EQ(encode_channel(0.18f, true), 118);  // 117.646
  EXPECT_EQ(encode_channel(0.002f, true), 7);   // linear segment: 6.589
  EXPECT_EQ(encode_channel(1.0f, true), 255);
  EXPECT_EQ(encode_channel(1.7f, true), 255);
  EXPECT_EQ(encode_channel(-1.0f, true), 0);
  EXPECT_EQ(encode_channel(std::numeric_limits<float>::quiet_NaN(), true), 0);
}

TEST(ImageIo, PfmRoundTripIsBitExact) {
  ScratchFolder folder;
  Image image(3, 2);
  const float values[] = {0.1f,  -5.5f,     1.0f / 3.0f, 3.4e38f,  1e-40f /* denormal */,
                          -0.0f, 7.0f,      0.0f,        65504.5f, 1e-7f,
                          2.0f,  0.999999f, 42.0f,       -1e-20f,  0.5f,
                          1e6f,  3.0f,      0.25f};
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    image.pixels[i] = glm::vec3(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
  }
  const std::string path = folder.file("image.pfm");
  write_pfm(path, image);
  const Image back = read_pfm(path);
  ASSERT_EQ(back.width, 3);
  ASSERT_EQ(back.height, 2);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_TRUE(same_bits(back.pixels[i][c], image.pixels[i][c])) << "pixel " << i << " c " << c;
    }
  }
}

TEST(ImageIo, PfmHasLittleEndianHeaderAndBottomRowFirst) {
  ScratchFolder folder;
  Image image(2, 2);
  image.at(0, 0) = glm::vec3(1.0f, 2.0f, 3.0f);     // top left
  image.at(1, 0) = glm::vec3(4.0f, 5.0f, 6.0f);     // top right
  image.at(0, 1) = glm::vec3(7.0f, 8.0f, 9.0f);     // bottom left
  image.at(1, 1) = glm::vec3(10.0f, 11.0f, 12.0f);  // bottom right
  const std::string path = folder.file("order.pfm");
  write_pfm(path, image);
  const std::string bytes = read_bytes(path);
  const std::string header = "PF\n2 2\n-1.0\n";
  ASSERT_EQ(bytes.size(), header.size() + 4 * 3 * 4);
  EXPECT_EQ(bytes.substr(0, header.size()), header);
  const float expected[] = {7, 8, 9, 10, 11, 12, 1, 2, 3, 4, 5, 6};
  for (int i = 0; i < 12; ++i) {
    EXPECT_EQ(little_endian_float(bytes, header.size() + 4 * i), expected[i]) << "float " << i;
  }
}

TEST(ImageIo, ReadPfmAcceptsBigEndianAndGrey) {
  ScratchFolder folder;
  // 1x2 big-endian (positive scale) colour image: bottom row (0.5, 1, 2), top row (3, 4, 5).
  std::string big = "PF\n1 2\n1.0\n";
  for (float v : {0.5f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f}) big += big_endian_bytes(v);
  write_bytes(folder.file("big.pfm"), big);
  const Image image = read_pfm(folder.file("big.pfm"));
  EXPECT_EQ(image.at(0, 0), glm::vec3(3.0f, 4.0f, 5.0f));
  EXPECT_EQ(image.at(0, 1), glm::vec3(0.5f, 1.0f, 2.0f));
  // Greyscale ("Pf"): one float per pixel, copied to all three channels.
  write_bytes(folder.file("grey.pfm"), "Pf\n1 1\n1\n" + big_endian_bytes(0.25f));
  EXPECT_EQ(read_pfm(folder.file("grey.pfm")).at(0, 0), glm::vec3(0.25f));
}

TEST(ImageIo, ReadPfmRejectsSizeMismatchAndBadHeader) {
  ScratchFolder folder;
  const std::string short_path = folder.file("short.pfm");
  write_bytes(short_path, "PF\n2 2\n-1.0\n" + std::string(47, '\0'));  // needs 48 bytes
  try {
    read_pfm(short_path);
    ADD_FAILURE() << "a truncated PFM was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), short_path);
  }
  write_bytes(folder.file("long.pfm"), "PF\n1 1\n-1.0\n" + std::string(13, '\0'));
  EXPECT_THROW(read_pfm(folder.file("long.pfm")), InputError);
  write_bytes(folder.file("magic.pfm"), "P6\n1 1\n255\n\0\0\0");
  EXPECT_THROW(read_pfm(folder.file("magic.pfm")), InputError);
  write_bytes(folder.file("zero.pfm"), "PF\n0 1\n-1.0\n");
  EXPECT_THROW(read_pfm(folder.file("zero.pfm")), InputError);
  write_bytes(folder.file("scale.pfm"), "PF\n1 1\n0\n" + std::string(12, '\0'));
  EXPECT_THROW(read_pfm(folder.file("scale.pfm")), InputError);
  EXPECT_THROW(read_pfm(folder.file("absent.pfm")), InputError);
}

TEST(ImageIo, PngRoundTripOfKnownValues) {
  ScratchFolder folder;
  Image image(5, 2);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  image.at(0, 0) = glm::vec3(0.5f, 1.7f, -1.0f);
  image.at(1, 0) = glm::vec3(nan, 0.0f, 1.0f);
  image.at(2, 0) = glm::vec3(0.25f, 0.75f, 0.2f);
  image.at(4, 1) = glm::vec3(0.5f, 0.2f, 0.002f);
  const std::string classic_path = folder.file("classic.png");
  const std::string srgb_path = folder.file("srgb.png");
  write_png(classic_path, image);
  write_png(srgb_path, image, true);

  const Png8 classic = read_png(classic_path);
  ASSERT_EQ(classic.width, 5);
  ASSERT_EQ(classic.height, 2);
  ASSERT_EQ(classic.rgb.size(), 5u * 2u * 3u);
  auto at = [](const Png8& png, int x, int y, int c) {
    return static_cast<int>(png.rgb[(static_cast<std::size_t>(y) * png.width + x) * 3 + c]);
  };
  EXPECT_EQ(at(classic, 0, 0, 0), 128);
  EXPECT_EQ(at(classic, 0, 0, 1), 255);
  EXPECT_EQ(at(classic, 0, 0, 2), 0);
  EXPECT_EQ(at(classic, 1, 0, 0), 0);
  EXPECT_EQ(at(classic, 1, 0, 2), 255);
  EXPECT_EQ(at(classic, 2, 0, 0), 64);
  EXPECT_EQ(at(classic, 2, 0, 1), 191);
  EXPECT_EQ(at(classic, 2, 0, 2), 51);
  EXPECT_EQ(at(classic, 3, 1, 0), 0);
  EXPECT_EQ(at(classic, 4, 1, 0), 128);  // row 1 is the bottom row: order is kept

  const Png8 srgb = read_png(srgb_path);
  EXPECT_EQ(at(srgb, 0, 0, 0), 188);
  EXPECT_EQ(at(srgb, 0, 0, 1), 255);
  EXPECT_EQ(at(srgb, 0, 0, 2), 0);
  EXPECT_EQ(at(srgb, 1, 0, 0), 0);
  EXPECT_EQ(at(srgb, 4, 1, 0), 188);
  EXPECT_EQ(at(srgb, 4, 1, 1), 124);
  EXPECT_EQ(at(srgb, 4, 1, 2), 7);
}

// The display transform on the way to 8 bits (display/display_transform.h), worked by hand.
TEST(ImageIo, PngGoesThroughTheDisplayTransform) {
  ScratchFolder folder;
  Image image(2, 1);
  image.at(0, 0) = glm::vec3(0.3f, 0.6f, 3.0f);
  image.at(1, 0) = glm::vec3(0.6f, 100.0f, -2.0f);
  DisplayTransform display;
  display.gain = 2.0f;  // +1 stop
  display.tone = ToneCurve::reinhard;
  const std::string path = folder.file("toned.png");
  write_png(path, image, display);
  const Png8 png = read_png(path);
  // 0.6 / 1.6 = 0.375 -> 95.6 -> 96; 1.2 / 2.2 -> 139.1 -> 139; 6 / 7 -> 218.6 -> 219.
  EXPECT_EQ(png.rgb[0], 96);
  EXPECT_EQ(png.rgb[1], 139);
  EXPECT_EQ(png.rgb[2], 219);
  // 1.2 / 2.2 again; 200 / 201 -> 253.7 -> 254 (Reinhard never clips); negatives 0.
  EXPECT_EQ(png.rgb[3], 139);
  EXPECT_EQ(png.rgb[4], 254);
  EXPECT_EQ(png.rgb[5], 0);
}

TEST(ImageIo, PngTextChunksRoundTrip) {
  ScratchFolder folder;
  const std::string long_text(3000, 'x');  // over 1 KB: stored compressed
  const TextChunks text = {{"gloss:scene", R"({"camera": {"fov_y": 40}})"},
                           {"gloss:materials", long_text},
                           {"Comment", "m\xC3\xA9tal"}};  // UTF-8: stored as iTXt
  const std::string path = folder.file("text.png");
  write_png(path, Image(2, 2, glm::vec3(0.5f)), false, text);
  EXPECT_EQ(read_png(path).text, text);
  const std::string bytes = read_bytes(path);
  EXPECT_NE(bytes.find("tEXtgloss:scene"), std::string::npos);
  EXPECT_NE(bytes.find("zTXtgloss:materials"), std::string::npos);
  EXPECT_NE(bytes.find("iTXtComment"), std::string::npos);
  EXPECT_EQ(bytes.find(long_text), std::string::npos);
}

TEST(ImageIo, WritingIntoAMissingFolderThrowsAndLeavesNoFile) {
  ScratchFolder folder;
  const std::string png_path = folder.file("missing/out.png");
  const std::string pfm_path = folder.file("missing/out.pfm");
  try {
    write_png(png_path, Image(2, 2));
    ADD_FAILURE() << "write_png into a missing folder succeeded";
  } catch (const RuntimeFailure& error) {
    EXPECT_NE(std::string(error.what()).find(png_path), std::string::npos) << error.what();
  }
  EXPECT_THROW(write_pfm(pfm_path, Image(2, 2)), RuntimeFailure);
  EXPECT_TRUE(folder.entries().empty());
}

TEST(ImageIo, InvalidImageOrKeywordThrowsAndLeavesNoFile) {
  ScratchFolder folder;
  EXPECT_THROW(write_png(folder.file("empty.png"), Image()), RuntimeFailure);
  EXPECT_THROW(write_pfm(folder.file("empty.pfm"), Image()), RuntimeFailure);
  Image inconsistent(2, 2);
  inconsistent.pixels.pop_back();
  EXPECT_THROW(write_png(folder.file("bad.png"), inconsistent), RuntimeFailure);
  EXPECT_THROW(write_png(folder.file("key.png"), Image(1, 1), false, {{" spaced", "x"}}),
               RuntimeFailure);
  EXPECT_THROW(write_png(folder.file("key.png"), Image(1, 1), false, {{"", "x"}}), RuntimeFailure);
  EXPECT_TRUE(folder.entries().empty());
}

TEST(ImageIo, ReadPngRejectsNonPngAndTruncatedFiles) {
  ScratchFolder folder;
  write_bytes(folder.file("not.png"), "GIF89a not a png at all");
  EXPECT_THROW(read_png(folder.file("not.png")), InputError);
  EXPECT_THROW(read_png(folder.file("absent.png")), InputError);
  // A real PNG cut in half fails inside libpng: the error must come back as an InputError.
  const std::string whole = folder.file("whole.png");
  Image noise(64, 64);
  for (std::size_t i = 0; i < noise.pixels.size(); ++i) {
    noise.pixels[i] = glm::vec3(static_cast<float>((i * 7919) % 256) / 255.0f);
  }
  write_png(whole, noise);
  const std::string bytes = read_bytes(whole);
  const std::string cut = folder.file("cut.png");
  write_bytes(cut, bytes.substr(0, bytes.size() / 2));
  try {
    read_png(cut);
    ADD_FAILURE() << "a truncated PNG was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), cut);
  }
}

// CRC-32 of PNG chunks (ISO 3309, polynomial 0xEDB88320), bit by bit as in the PNG spec's sample
// code, so the test builds valid headers without the library under test.
std::uint32_t png_crc(const std::string& bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (const char byte : bytes) {
    crc ^= static_cast<unsigned char>(byte);
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xFFFFFFFFu;
}

std::string big_endian(std::uint32_t value) {
  return {static_cast<char>(value >> 24), static_cast<char>(value >> 16),
          static_cast<char>(value >> 8), static_cast<char>(value)};
}

std::string png_chunk(const std::string& type, const std::string& data) {
  return big_endian(static_cast<std::uint32_t>(data.size())) + type + data +
         big_endian(png_crc(type + data));
}

// A 57-byte PNG: a valid header for width x height 8-bit RGB, an empty IDAT, IEND.
std::string png_header_only(std::uint32_t width, std::uint32_t height) {
  const std::string ihdr =
      big_endian(width) + big_endian(height) + std::string("\x08\x02\0\0\0", 5);
  return std::string("\x89PNG\r\n\x1a\n", 8) + png_chunk("IHDR", ihdr) + png_chunk("IDAT", "") +
         png_chunk("IEND", "");
}

// Found while writing fuzz/fuzz_png (by hand: the fuzzer cannot forge the header's CRC): the pixel
// buffer (width x height x 3 bytes) was allocated from the header alone, so 57 bytes claiming
// 100000 x 100000 asked for 30 GB (std::bad_alloc, or an AddressSanitizer abort). A header past
// gloss's largest image (16384, scene/render_settings.h) is refused by libpng; one within it but
// beyond what the file can inflate to (deflate: 1032:1) is refused before allocating. (The same
// bound on libpng's own allocations, against a text chunk declaring 1.9 GB, cannot be seen from
// here; fuzz/corpus/png replays that input.)
TEST(ImageIo, ReadPngRefusesHeadersTheFileCannotHold) {
  ScratchFolder folder;
  const struct {
    std::uint32_t width, height;
    const char* words;
  } cases[] = {{100000, 100000, "Invalid IHDR data"},
               {16385, 1, "Invalid IHDR data"},
               {16384, 16384, "claims 16384x16384 pixels, more than its 57 bytes can hold"},
               // 8 x 2466 x 3 = 59184 bytes of pixels, 360 more than 1032 x 57 = 58824.
               {8, 2466, "claims 8x2466 pixels"}};
  for (const auto& c : cases) {
    const std::string path = folder.file("header.png");
    write_bytes(path, png_header_only(c.width, c.height));
    ASSERT_EQ(read_bytes(path).size(), 57u);
    try {
      read_png(path);
      ADD_FAILURE() << c.width << "x" << c.height << " was accepted";
    } catch (const InputError& error) {
      EXPECT_EQ(error.file(), path);
      EXPECT_NE(std::string(error.what()).find(c.words), std::string::npos) << error.what();
    }
  }
  // Within the bound (8 x 2450 x 3 = 58800 <= 58824) the header passes and libpng then finds
  // the image data missing: still an InputError, after a buffer the file could have filled.
  write_bytes(folder.file("small.png"), png_header_only(8, 2450));
  try {
    read_png(folder.file("small.png"));
    ADD_FAILURE() << "an empty IDAT was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).find("can hold"), std::string::npos) << error.what();
  }
}

TEST(ImageIo, TermNamesAndImagesMatch) {
  TermImages terms;
  terms.emissive = Image(1, 1);
  terms.ambient = Image(2, 1);
  terms.diffuse = Image(3, 1);
  terms.specular = Image(4, 1);
  terms.total = Image(5, 1);
  const std::pair<Term, const char*> expected[] = {{Term::emissive, "emissive"},
                                                   {Term::ambient, "ambient"},
                                                   {Term::diffuse, "diffuse"},
                                                   {Term::specular, "specular"},
                                                   {Term::total, "total"}};
  int width = 1;
  for (const auto& [term, name] : expected) {
    EXPECT_STREQ(to_string(term), name);
    EXPECT_EQ(term_image(terms, term).width, width++) << name;
  }
}

}  // namespace
}  // namespace gloss

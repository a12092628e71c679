// JPEG maps (io/image/jpeg_reader.cpp, through image_reader.h): flat-colour files written by
// ImageMagick (tests/data/jpeg, quality 100, no chroma subsampling, so the decoded value is the
// written one to a unit) read into floats, as colour (sRGB decoded) and as data (v/255); Adobe
// CMYK back to RGB; and corrupt files refused in one line naming them: truncated, cut inside the
// header, and the two progressive files fuzz_jpeg found that made stb_image abort on an
// assertion (its Huffman tables read before they were defined).
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "base/error.h"
#include "io/image/image_reader.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

const std::string kFolder = std::string(GLOSS_TEST_DATA_DIR) + "/jpeg/";

double srgb(double v) {  // the sRGB curve's inverse, by hand
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

FloatImage read(const std::string& name, ImageData data) {
  ImageReadOptions options;
  options.data = data;
  return read_image(kFolder + name, options);
}

std::string error_of(const std::string& path) {
  try {
    read_image(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(JpegReader, BaselineAndProgressiveColourAsWritten) {
  // rgb(200,100,50) everywhere; one unit of 255 is what the DCT may round away.
  for (const char* name : {"flat-rgb.jpg", "flat-rgb-progressive.jpg", "flat-cmyk.jpg"}) {
    const FloatImage data = read(name, ImageData::linear);
    ASSERT_EQ(data.width, 8) << name;
    ASSERT_EQ(data.height, 8) << name;
    ASSERT_EQ(data.channels, 3) << name;
    const FloatImage colour = read(name, ImageData::colour);
    const double written[3] = {200, 100, 50};
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(data.at(3, 5, c), written[c] / 255.0, 1.01 / 255.0) << name << " " << c;
      // Decoded as sRGB: 200 -> 0.5776, 100 -> 0.1274, 50 -> 0.0319 (the curve by hand), each
      // within the curve's slope times one unit.
      const double unit = srgb((written[c] + 1) / 255.0) - srgb(written[c] / 255.0);
      EXPECT_NEAR(colour.at(3, 5, c), srgb(written[c] / 255.0), 1.01 * unit) << name << " " << c;
    }
  }
}

TEST(JpegReader, GreyStaysOneChannel) {
  // gray(30%): 0.3 * 255 = 76.5, written as 77.
  const FloatImage grey = read("flat-grey.jpg", ImageData::linear);
  ASSERT_EQ(grey.channels, 1);
  ASSERT_EQ(grey.width, 5);
  ASSERT_EQ(grey.height, 3);
  EXPECT_NEAR(grey.at(4, 2, 0), 77 / 255.0, 1.01 / 255.0);
}

TEST(JpegReader, CorruptFilesAreOneLineErrorsNamingTheFile) {
  ScratchFolder folder;
  std::ifstream in(kFolder + "noise-48.jpg", std::ios::binary);
  const std::string whole((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(whole.size(), 1000u);
  const auto cut = [&](const std::string& name, std::size_t keep) {
    const std::string path = folder.file(name);
    std::ofstream(path, std::ios::binary) << whole.substr(0, keep);
    return path;
  };
  // Cut inside the entropy-coded data: halfway between the start of scan and the end.
  const std::size_t scan = whole.find("\xff\xda");
  ASSERT_NE(scan, std::string::npos);
  const std::string truncated = error_of(cut("truncated.jpg", (scan + whole.size()) / 2));
  EXPECT_NE(truncated.find("truncated.jpg: invalid JPEG: the image data is truncated"),
            std::string::npos)
      << truncated;
  const std::string header = error_of(cut("header.jpg", 30));
  EXPECT_NE(header.find("header.jpg: invalid JPEG: "), std::string::npos) << header;
  // fuzz_jpeg's findings: libjpeg decodes or refuses them; either way no abort, and a refusal
  // names the file.
  for (const char* name : {"corrupt-progressive-1.jpg", "corrupt-progressive-2.jpg"}) {
    const std::string outcome = error_of(kFolder + name);
    if (outcome != "accepted") {
      EXPECT_NE(outcome.find(name), std::string::npos) << outcome;
    }
  }
  for (const std::string& line : {truncated, header}) {
    EXPECT_EQ(line.find('\n'), std::string::npos) << line;
  }
}

TEST(JpegReader, ProgressiveCoefficientsCountAgainstTheBudget) {
  // 512 x 512 RGB, progressive, no subsampling: the file (3601 B), its decoded bytes (768 KB)
  // and floats (3 MB) make 3935761 B; libjpeg keeps 3 * 4096 blocks * 128 B = 1.5 MB of DCT
  // coefficients besides until the last scan. 8 MB reads it; 4 MB (which the floats alone fit,
  // 258543 B to spare) is refused by libjpeg's memory limit.
  const std::string path = kFolder + "flat-512-progressive.jpg";
  ImageReadOptions roomy;
  roomy.budget_bytes = std::uint64_t(8) << 20;
  EXPECT_EQ(read_image(path, roomy).width, 512);
  ImageReadOptions tight;
  tight.budget_bytes = std::uint64_t(4) << 20;
  try {
    read_image(path, tight);
    ADD_FAILURE() << "read 1.5 MB of coefficients within 258543 B";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("flat-512-progressive.jpg: JPEG of 512x512 pixels needs "
                                         "more than the memory budget of 4 MB to decode"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace gloss

// The EXR writer: the linear image read back bit for bit by OpenEXR itself (32-bit float, values
// above 1, negative and tiny ones, every pixel in its place), and no file left by a failure.
#include "io/image/exr_writer.h"

#include <cstring>
#include <limits>

#include <gtest/gtest.h>

#include "base/error.h"
#include "support/exr_file.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

bool same_bits(float a, float b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(ExrWriter, RoundTripThroughOpenExrIsExact) {
  ScratchFolder folder;
  Image image(7, 3);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 7; ++x) {
      image.at(x, y) = glm::vec3(0.1f * static_cast<float>(x), 10.0f * static_cast<float>(y),
                                 static_cast<float>(x * 3 + y));
    }
  }
  image.at(0, 0) = glm::vec3(1e6f, -0.25f, std::numeric_limits<float>::denorm_min());
  image.at(6, 2) = glm::vec3(0.123456789f, 3.0e-8f, 65504.5f);  // past half's range and precision
  const std::string path = folder.file("linear.exr");
  write_exr(path, image);
  const test::ExrFile back = test::read_exr_file(path);
  EXPECT_TRUE(back.float_channels);
  EXPECT_EQ(back.compression, Imf::ZIP_COMPRESSION);
  ASSERT_EQ(back.image.width, 7);
  ASSERT_EQ(back.image.height, 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_TRUE(same_bits(back.image.pixels[i][c], image.pixels[i][c]))
          << i << " " << c << ": " << back.image.pixels[i][c] << " vs " << image.pixels[i][c];
    }
  }
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"linear.exr"});  // no temporary left
}

TEST(ExrWriter, FailuresThrowAndLeaveNoFile) {
  ScratchFolder folder;
  try {
    write_exr(folder.file("missing/out.exr"), Image(2, 2));
    ADD_FAILURE() << "write_exr into a missing folder succeeded";
  } catch (const RuntimeFailure& error) {
    EXPECT_NE(std::string(error.what()).find("missing/out.exr"), std::string::npos);
  }
  EXPECT_THROW(write_exr(folder.file("empty.exr"), Image()), RuntimeFailure);
  Image inconsistent(2, 2);
  inconsistent.pixels.pop_back();
  EXPECT_THROW(write_exr(folder.file("bad.exr"), inconsistent), RuntimeFailure);
  EXPECT_TRUE(folder.entries().empty());
}

}  // namespace
}  // namespace gloss

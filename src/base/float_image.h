#pragma once
// A decoded image as every map reader gives it (io/image/image_reader.h): linear float samples,
// `channels` per pixel (1 grey, 2 grey and alpha, 3 RGB, 4 RGBA), row-major, row 0 at the top.
// Environment maps and textures start from one of these.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace gloss {

struct FloatImage {
  int width = 0, height = 0;
  int channels = 0;
  std::vector<float> samples;  // width * height * channels

  float at(int x, int y, int c) const {
    return samples[(static_cast<std::size_t>(y) * width + x) * channels + c];
  }
  std::uint64_t bytes() const { return samples.size() * sizeof(float); }
};

}  // namespace gloss

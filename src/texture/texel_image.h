#pragma once
// An image made texel by texel from a function: the maps gloss makes itself (the UV checker, a
// model's maps converted per texel) and the tests' maps.
#include <cstddef>
#include <utility>

#include "base/float_image.h"

namespace gloss {

// A width x height image of `channels` (1 to 4) samples per texel: texel (i, j), row j counted
// from the top, holds the first `channels` components of texel(i, j) (a glm::vec3 or vec4 with at
// least that many).
template <class TexelFn>
FloatImage texel_image(int width, int height, int channels, TexelFn&& texel) {
  FloatImage image;
  image.width = width;
  image.height = height;
  image.channels = channels;
  image.samples.resize(static_cast<std::size_t>(width) * height * channels);
  float* out = image.samples.data();
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const auto t = texel(i, j);
      for (int c = 0; c < channels; ++c) *out++ = t[c];
    }
  }
  return image;
}

}  // namespace gloss

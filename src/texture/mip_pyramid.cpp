#include "texture/mip_pyramid.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace gloss {

namespace {

// The source texels new texel i of a side of n takes, and their weights (see mip_pyramid.h).
struct Taps {
  int first = 0, count = 1;
  double weight[3] = {1.0, 0.0, 0.0};
};

Taps taps(int i, int n) {
  Taps t;
  if (n == 1) return t;  // a side of 1 stays 1
  if (n % 2 == 0) {
    t.first = 2 * i;
    t.count = 2;
    t.weight[0] = t.weight[1] = 0.5;
    return t;
  }
  const int m = n / 2;
  t.first = 2 * i;
  t.count = 3;
  t.weight[0] = static_cast<double>(m - i) / n;
  t.weight[1] = static_cast<double>(m) / n;
  t.weight[2] = static_cast<double>(i + 1) / n;
  return t;
}

}  // namespace

std::uint64_t Texture::bytes() const {
  std::uint64_t total = 0;
  for (const MipLevel& level : levels) total += level.texels.size() * sizeof(float);
  return total;
}

std::uint64_t pyramid_bytes(int width, int height, int channels) {
  std::uint64_t texels = 0;
  for (std::uint64_t w = std::max(width, 1), h = std::max(height, 1);;
       w = std::max<std::uint64_t>(1, w / 2), h = std::max<std::uint64_t>(1, h / 2)) {
    texels += w * h;
    if (w == 1 && h == 1) break;
  }
  return texels * static_cast<std::uint64_t>(channels) * 4;
}

int stored_channels(int image_channels) {
  return image_channels == 1 ? 1 : 4;
}

MipLevel downsample(const MipLevel& level, int channels) {
  MipLevel out;
  out.width = std::max(1, level.width / 2);
  out.height = std::max(1, level.height / 2);
  out.texels.assign(static_cast<std::size_t>(out.width) * out.height * channels, 0.0f);
  std::vector<double> sum(static_cast<std::size_t>(channels));
  for (int j = 0; j < out.height; ++j) {
    const Taps ty = taps(j, level.height);
    for (int i = 0; i < out.width; ++i) {
      const Taps tx = taps(i, level.width);
      std::fill(sum.begin(), sum.end(), 0.0);
      for (int b = 0; b < ty.count; ++b) {
        const std::size_t row = static_cast<std::size_t>(ty.first + b) * level.width;
        for (int a = 0; a < tx.count; ++a) {
          const double w = ty.weight[b] * tx.weight[a];
          const float* texel = &level.texels[(row + tx.first + a) * channels];
          for (int c = 0; c < channels; ++c) sum[c] += w * texel[c];
        }
      }
      float* texel = &out.texels[(static_cast<std::size_t>(j) * out.width + i) * channels];
      for (int c = 0; c < channels; ++c) texel[c] = static_cast<float>(sum[c]);
    }
  }
  return out;
}

Texture make_texture(FloatImage image) {
  Texture texture;
  texture.channels = stored_channels(image.channels);
  texture.has_alpha = image.channels == 2 || image.channels == 4;
  MipLevel base;
  base.width = image.width;
  base.height = image.height;
  if (texture.channels == image.channels) {
    base.texels = std::move(image.samples);
  } else {
    const std::size_t texels = static_cast<std::size_t>(image.width) * image.height;
    base.texels.resize(texels * 4);
    const int c = image.channels;
    for (std::size_t k = 0; k < texels; ++k) {
      const float* in = &image.samples[k * c];
      float* out = &base.texels[k * 4];
      if (c <= 2) {
        out[0] = out[1] = out[2] = in[0];
        out[3] = c == 2 ? in[1] : 1.0f;
      } else {
        out[0] = in[0];
        out[1] = in[1];
        out[2] = in[2];
        out[3] = 1.0f;
      }
    }
    image.samples = {};
  }
  texture.levels.push_back(std::move(base));
  while (texture.levels.back().width > 1 || texture.levels.back().height > 1) {
    MipLevel next = downsample(texture.levels.back(), texture.channels);
    texture.levels.push_back(std::move(next));
  }
  return texture;
}

}  // namespace gloss

#pragma once
// Mip pyramids in linear float (docs/spec/shading.md, "Textures": the image is decoded to linear
// before any filtering). Each level halves the previous one's sides (rounding down, at least 1)
// with a box filter over exactly the area each new texel covers: 2 taps of 1/2 on an even side,
// 3 taps of (m - i) / n, m / n, (i + 1) / n on an odd side n = 2m + 1 (new texel i of m), the
// weights of NVIDIA's "Non-power-of-two mipmapping" (2002): every old texel gives all of its
// weight, so a level's mean is the image's mean.
#include <cstdint>

#include "base/float_image.h"
#include "texture/texture.h"

namespace gloss {

// How many bytes a pyramid of a w x h image with `channels` stored floats per texel holds (about
// 4/3 of level 0, up to twice it for a strip): the memory budget counts this before anything is
// allocated.
std::uint64_t pyramid_bytes(int width, int height, int channels);

// The channels a texture keeps for an image of `image_channels` (1 grey, 2 grey and alpha, 3 RGB,
// 4 RGBA): 1 for grey without alpha, else 4.
int stored_channels(int image_channels);

// The pyramid of image (any of 1 to 4 channels; grey and alpha become (g, g, g, a), RGB gets
// alpha 1). Takes the samples by value: level 0 reuses their memory where it can.
Texture make_texture(FloatImage image);

// The next level of `level` (channels floats per texel), by the filter above.
MipLevel downsample(const MipLevel& level, int channels);

}  // namespace gloss

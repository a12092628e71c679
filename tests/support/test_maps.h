#pragma once
// Maps made in memory for the tests (no files): each a Texture from make_texture, with values
// a person can write down, and a TextureMap around it.
#include <cmath>
#include <functional>
#include <memory>
#include <string>

#include "scene/material.h"
#include "texture/mip_pyramid.h"
#include "texture/texel_image.h"

namespace gloss::test {

// A w x h texture with `channels` (1 or 4) of texel(i, j) (j from the top row).
inline std::shared_ptr<const Texture> texture_of(int w, int h, int channels,
                                                 const std::function<glm::vec4(int, int)>& texel) {
  auto texture = std::make_shared<Texture>(make_texture(texel_image(w, h, channels, texel)));
  texture->source = "test";
  return texture;
}

// Checks of `tile` texels, dark blue and light grey.
inline std::shared_ptr<const Texture> checker(int side, int tile) {
  return texture_of(side, side, 4, [tile](int i, int j) {
    return ((i / tile) + (j / tile)) % 2 == 0 ? glm::vec4(0.9f, 0.9f, 0.85f, 1.0f)
                                              : glm::vec4(0.1f, 0.15f, 0.6f, 1.0f);
  });
}

// Red along u, green up v: the texel's own coordinates, to read (u, v) off an image.
inline std::shared_ptr<const Texture> uv_ramp(int side) {
  return texture_of(side, side, 4, [side](int i, int j) {
    return glm::vec4((i + 0.5f) / side, 1.0f - (j + 0.5f) / side, 0.25f, 1.0f);
  });
}

// A tangent-space normal map of ripples along u and v (2 c - 1 = the normal).
inline std::shared_ptr<const Texture> ripples(int side, float amplitude) {
  return texture_of(side, side, 4, [side, amplitude](int i, int j) {
    const float x = amplitude * std::sin(6.2831853f * 4.0f * i / side);
    const float y = amplitude * std::sin(6.2831853f * 3.0f * j / side);
    const float z = std::sqrt(std::max(0.0f, 1.0f - x * x - y * y));
    return glm::vec4(0.5f * x + 0.5f, 0.5f * y + 0.5f, 0.5f * z + 0.5f, 1.0f);
  });
}

// A height field of bumps (one channel).
inline std::shared_ptr<const Texture> bumps(int side) {
  return texture_of(side, side, 1, [side](int i, int j) {
    return glm::vec4(0.5f + 0.5f * std::sin(6.2831853f * 3.0f * i / side) *
                                std::sin(6.2831853f * 2.0f * j / side));
  });
}

// Round holes (opacity 0) in an opaque sheet, one channel.
inline std::shared_ptr<const Texture> holes(int side, int period) {
  return texture_of(side, side, 1, [period](int i, int j) {
    const int x = i % period - period / 2, y = j % period - period / 2;
    return glm::vec4(x * x + y * y < period * period / 9 ? 0.0f : 1.0f);
  });
}

inline TextureMap map_of(std::shared_ptr<const Texture> texture, const std::string& name) {
  TextureMap map;
  map.file = name;
  map.texture = std::move(texture);
  return map;
}

}  // namespace gloss::test

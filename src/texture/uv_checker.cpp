#include "texture/uv_checker.h"

#include <cmath>
#include <mutex>

#include "texture/mip_pyramid.h"
#include "texture/texel_image.h"

namespace gloss {

namespace {

// HSV to RGB with saturation 1: hue in [0, 1) around the wheel, value the largest channel.
glm::vec3 hue_colour(float hue, float value) {
  const float h = hue * 6.0f;
  const int sector = static_cast<int>(h) % 6;
  const float f = h - std::floor(h);
  const float rising = value * f, falling = value * (1.0f - f);
  switch (sector) {
    case 0:
      return {value, rising, 0.0f};
    case 1:
      return {falling, value, 0.0f};
    case 2:
      return {0.0f, value, rising};
    case 3:
      return {0.0f, falling, value};
    case 4:
      return {rising, 0.0f, value};
    default:
      return {value, 0.0f, falling};
  }
}

}  // namespace

glm::vec3 uv_checker_texel(int x, int y, int side) {
  const int cell = side / kUvCheckerCells;
  const int up = side - 1 - y;  // rows counted from the bottom: v grows upwards
  const int marker = side / 32;
  if (x < marker && up < marker) return glm::vec3(1.0f);
  const int ix = x % cell, iy = up % cell;
  if (ix == 0 || iy == 0 || ix == cell - 1 || iy == cell - 1) return glm::vec3(0.02f);
  const int i = x / cell, j = up / cell;
  const float value = 0.2f + 0.8f * static_cast<float>(j) / (kUvCheckerCells - 1);
  const glm::vec3 colour = hue_colour(static_cast<float>(i) / kUvCheckerCells, value);
  if ((i + j) % 2 == 0) return colour;
  return colour * 0.4f + glm::vec3(value * 0.6f);
}

Texture make_uv_checker(int side) {
  Texture texture = make_texture(
      texel_image(side, side, 3, [side](int x, int y) { return uv_checker_texel(x, y, side); }));
  texture.source = "UV checker";
  texture.format = "made by gloss";
  texture.bits = 32;
  return texture;
}

std::shared_ptr<const Texture> shared_uv_checker() {
  // Made once (about 5.6 MB with its levels), on the first thread that asks.
  static std::once_flag once;
  static std::shared_ptr<const Texture> checker;
  std::call_once(once, [] { checker = std::make_shared<const Texture>(make_uv_checker()); });
  return checker;
}

}  // namespace gloss

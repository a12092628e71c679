#pragma once
// One image map of a material (docs/spec/shading.md, "Textures"): the file it comes from, how
// (u, v) reach it (wrap per axis, scale, rotation, offset, texture coordinate set) and its mip
// pyramid, immutable and shared as meshes are (copies of the scene share it; swapping it is a
// pointer change).
#include <array>
#include <cmath>
#include <memory>
#include <string>

#include <glm/vec2.hpp>

#include "texture/texture.h"

namespace gloss {

// The maps a material may give, in the order of its table (scene/fields/fields.cpp).
enum class MapSlot : int {
  diffuse,    // kd times the map (and ka, unless an ambient map is given)
  ambient,    // ka times the map
  specular,   // ks times the map
  emission,   // ke times the map
  shininess,  // alpha times the map's first channel
  opacity,    // no surface where the map (its alpha, else its first channel) is below 0.5
  normal,     // tangent-space normal, +Y up, x and y times normal_scale
  bump,       // height times bump_scale, scene units
};
inline constexpr int kMapSlots = 8;

// "diffuse" ... "bump".
const char* to_string(MapSlot slot);

// The material field that holds a slot's map ("diffuse_map" ...), and back (false: no map field).
std::string map_key(MapSlot slot);
bool map_slot_of_key(const std::string& key, MapSlot& slot);

// Whether a slot holds colour (sRGB-encoded unless the file says linear) or data (linear).
inline bool is_colour_map(MapSlot slot) {
  return slot == MapSlot::diffuse || slot == MapSlot::ambient || slot == MapSlot::specular ||
         slot == MapSlot::emission;
}

struct TextureMap {
  // The image as the scene names it (relative to the scene file's folder), or a model's map as
  // `MODEL#MATERIAL/SLOT` (io/model/model_maps.h); "" with no map.
  std::string file;
  std::array<Wrap, 2> wrap{Wrap::repeat, Wrap::repeat};  // u, v
  glm::vec2 scale{1.0f};  // (u, v) * scale, then rotated, then + offset
  float rotation = 0.0f;  // degrees, counter-clockwise in (u, v) (v up)
  glm::vec2 offset{0.0f};
  int uv_set = 0;                          // 0 or 1; shapes with one set read set 0 for either
  std::shared_ptr<const Texture> texture;  // null: not read yet, or no map

  bool present() const { return texture != nullptr; }
  bool named() const { return !file.empty(); }
};

// Equal files, settings and the same pyramid.
bool operator==(const TextureMap& a, const TextureMap& b);
inline bool operator!=(const TextureMap& a, const TextureMap& b) {
  return !(a == b);
}

// Whether the map's settings are the defaults (repeat, no scale, rotation or offset, set 0): a
// scene file may then name it by its path alone.
bool plain_settings(const TextureMap& map);

// (u, v) as the map reads it: (u, v) * scale, rotated, plus offset.
template <class T>
glm::vec<2, T> map_coordinates(const TextureMap& map, const glm::vec<2, T>& uv) {
  const T x = uv.x * static_cast<T>(map.scale.x), y = uv.y * static_cast<T>(map.scale.y);
  if (map.rotation == 0.0f) {
    return {x + static_cast<T>(map.offset.x), y + static_cast<T>(map.offset.y)};
  }
  const T angle = static_cast<T>(map.rotation) * T(3.14159265358979323846) / T(180);
  const T c = std::cos(angle), s = std::sin(angle);
  return {c * x - s * y + static_cast<T>(map.offset.x),
          s * x + c * y + static_cast<T>(map.offset.y)};
}

}  // namespace gloss

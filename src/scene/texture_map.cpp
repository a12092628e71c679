#include "scene/texture_map.h"

#include <string>

#include "scene/material.h"

namespace gloss {

const char* to_string(MapSlot slot) {
  static const char* const names[kMapSlots] = {"diffuse",   "ambient", "specular", "emission",
                                               "shininess", "opacity", "normal",   "bump"};
  const int i = static_cast<int>(slot);
  return i >= 0 && i < kMapSlots ? names[i] : "?";
}

std::string map_key(MapSlot slot) {
  return std::string(to_string(slot)) + "_map";
}

bool map_slot_of_key(const std::string& key, MapSlot& slot) {
  for (int s = 0; s < kMapSlots; ++s) {
    if (key == map_key(static_cast<MapSlot>(s))) {
      slot = static_cast<MapSlot>(s);
      return true;
    }
  }
  return false;
}

bool operator==(const TextureMap& a, const TextureMap& b) {
  return a.file == b.file && a.wrap == b.wrap && a.scale == b.scale && a.rotation == b.rotation &&
         a.offset == b.offset && a.uv_set == b.uv_set && a.texture == b.texture;
}

bool plain_settings(const TextureMap& map) {
  const TextureMap defaults;
  return map.wrap == defaults.wrap && map.scale == defaults.scale &&
         map.rotation == defaults.rotation && map.offset == defaults.offset &&
         map.uv_set == defaults.uv_set;
}

const TextureMap& Material::map(MapSlot slot) const {
  static const TextureMap none;
  return map_storage ? (*map_storage)[static_cast<std::size_t>(slot)] : none;
}

TextureMap& Material::map(MapSlot slot) {
  using Maps = std::array<TextureMap, kMapSlots>;
  if (!map_storage || map_storage.use_count() > 1) {
    map_storage = map_storage ? std::make_shared<Maps>(*map_storage) : std::make_shared<Maps>();
  }
  // Ours alone now: the const is the sharing's promise to the other copies.
  return const_cast<Maps&>(*map_storage)[static_cast<std::size_t>(slot)];
}

bool Material::textured() const {
  if (!map_storage) return false;
  for (const TextureMap& m : *map_storage) {
    if (m.present()) return true;
  }
  return false;
}

Material with_constants(const Material& onto, const Material& from) {
  Material out = onto;
  out.ambient = from.ambient;
  out.diffuse = from.diffuse;
  out.specular = from.specular;
  out.emission = from.emission;
  out.shininess = from.shininess;
  out.preset = from.preset;
  out.reference = from.reference;
  return out;
}

}  // namespace gloss

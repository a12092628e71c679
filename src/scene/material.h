#pragma once
// A Phong material: the constants of docs/spec/shading.md. Colours are linear RGB, unclamped, >= 0.
// Its maps (docs/spec/shading.md, "Textures") multiply the constants; a preset sets only the
// constants (and its physical reference), so choosing one or resetting to it keeps the maps.
#include <array>
#include <memory>
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "scene/physical_reference.h"
#include "scene/texture_map.h"

namespace gloss {

struct Material {
  glm::vec3 ambient{0.2f};    // ka
  glm::vec3 diffuse{0.8f};    // kd
  glm::vec3 specular{0.0f};   // ks
  glm::vec3 emission{0.0f};   // ke
  float shininess = 32.0f;    // alpha, the Phong exponent, >= 0 (not the table's 0..1 fraction)
  std::string preset;         // preset the constants came from, empty when custom
  float normal_scale = 1.0f;  // the normal map's x and y times this (0: flat)
  float bump_scale = 1.0f;    // the bump map's height times this, scene units
  // The maps by MapSlot, shared between copies until one is changed (the undo history holds a
  // copy of the document per step); null: no map at all. Read and write through map(slot).
  std::shared_ptr<const std::array<TextureMap, kMapSlots>> map_storage;
  // The physical reference this material is compared with and fitted to (the `reference` block
  // of a material; docs/spec/physical-reference.md); none by default. The Phong renderer
  // ignores it.
  std::optional<PhysicalReference> reference;

  const TextureMap& map(MapSlot slot) const;
  // The slot to change: the maps are copied first when another Material shares them.
  TextureMap& map(MapSlot slot);
  bool has_map(MapSlot slot) const { return map(slot).present(); }
  // Whether any map is present.
  bool textured() const;
};

// The constants of `from` (ka, kd, ks, ke, shininess, the preset name and the physical
// reference) on `onto`, whose maps and map scales stay: what choosing a preset or resetting to
// it does.
Material with_constants(const Material& onto, const Material& from);

// Equal in every field of its table (scene/fields/fields.h), in preset and in reference.
bool operator==(const Material& a, const Material& b);
inline bool operator!=(const Material& a, const Material& b) {
  return !(a == b);
}

}  // namespace gloss

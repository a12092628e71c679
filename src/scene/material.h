#pragma once
// A Phong material: the constants of docs/spec/shading.md. Colours are linear RGB, unclamped, >= 0.
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "scene/physical_reference.h"

namespace gloss {

struct Material {
  glm::vec3 ambient{0.2f};   // ka
  glm::vec3 diffuse{0.8f};   // kd
  glm::vec3 specular{0.0f};  // ks
  glm::vec3 emission{0.0f};  // ke
  float shininess = 32.0f;   // alpha, the Phong exponent, >= 0 (not the table's 0..1 fraction)
  std::string preset;        // preset the constants came from, empty when custom
  // The physical reference this material is compared with and fitted to (the `reference` block
  // of a material; docs/spec/physical-reference.md); none by default. The Phong renderer
  // ignores it.
  std::optional<PhysicalReference> reference;
};

// Equal in every field of its table (scene/fields/fields.h), in preset and in reference.
bool operator==(const Material& a, const Material& b);
inline bool operator!=(const Material& a, const Material& b) {
  return !(a == b);
}

}  // namespace gloss

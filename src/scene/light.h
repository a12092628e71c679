#pragma once
// A point light of docs/spec/shading.md: colours La, Ld, Ls and attenuation
// 1 / (c0 + c1 d + c2 d^2).
#include <glm/vec3.hpp>

namespace gloss {

struct PointLight {
  glm::vec3 position{0.0f, 5.0f, 5.0f};     // world units
  glm::vec3 ambient{0.0f};                  // La, added to ka's ambient sum, never shadowed
  glm::vec3 diffuse{1.0f};                  // Ld
  glm::vec3 specular{1.0f};                 // Ls
  glm::vec3 attenuation{1.0f, 0.0f, 0.0f};  // (c0, c1, c2), non-negative, not all zero
};

// Equal in every field of its table (scene/fields/fields.h).
bool operator==(const PointLight& a, const PointLight& b);
inline bool operator!=(const PointLight& a, const PointLight& b) {
  return !(a == b);
}

}  // namespace gloss

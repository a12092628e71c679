#pragma once
// A Phong material: the constants of docs/spec/shading.md. Colours are linear RGB, unclamped, >= 0.
#include <string>

#include <glm/vec3.hpp>

namespace gloss {

struct Material {
  glm::vec3 ambient{0.2f};   // ka
  glm::vec3 diffuse{0.8f};   // kd
  glm::vec3 specular{0.0f};  // ks
  glm::vec3 emission{0.0f};  // ke
  float shininess = 32.0f;   // alpha, the Phong exponent, >= 0 (not the table's 0..1 fraction)
  std::string preset;        // preset the constants came from, empty when custom
};

inline bool operator==(const Material& a, const Material& b) {
  return a.ambient == b.ambient && a.diffuse == b.diffuse && a.specular == b.specular &&
         a.emission == b.emission && a.shininess == b.shininess && a.preset == b.preset;
}
inline bool operator!=(const Material& a, const Material& b) {
  return !(a == b);
}

}  // namespace gloss

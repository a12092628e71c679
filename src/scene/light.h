#pragma once
// A light of docs/spec/shading.md ("Light types"): colours La, Ld, Ls, and how it reaches a
// point: a point light (position, attenuation 1 / (c0 + c1 d + c2 d^2)), a directional light (a
// direction only, no attenuation) or a spot (a point light cut to a cone about its direction).
// Every field is kept whatever the type, so switching a light's type back restores what the
// other type used; the fields a type does not use are ignored (scene/fields/fields.cpp says
// which type uses which).
#include <glm/vec3.hpp>

namespace gloss {

enum class LightType { point, directional, spot };

// "point" / "directional" / "spot" (the names of the light table's `type` field).
const char* to_string(LightType type);

struct Light {
  LightType type = LightType::point;
  glm::vec3 position{0.0f, 5.0f, 5.0f};     // point, spot: world units
  glm::vec3 direction{0.0f, -1.0f, 0.0f};   // directional, spot: the way the light travels
                                            // (world space, or camera space when following
                                            // the camera); any length but 0
  glm::vec3 ambient{0.0f};                  // La, added to ka's ambient sum, never shadowed
  glm::vec3 diffuse{1.0f};                  // Ld
  glm::vec3 specular{1.0f};                 // Ls
  glm::vec3 attenuation{1.0f, 0.0f, 0.0f};  // point, spot: (c0, c1, c2), >= 0, not all zero
  float cutoff = 45.0f;                     // spot: cone half-angle, degrees, (0, 90]
  float inner = 90.0f;                      // spot: full-strength half-angle, degrees, used as
                                            // min(inner, cutoff): 90 keeps a hard OpenGL edge
  float exponent = 0.0f;                    // spot: cos_t^exponent fall-off, >= 0
  bool follow_camera = false;               // directional: direction in camera space (x right,
                                            // y up, -z ahead): a headlight
};

// The name the light was known by when it was a point light only; kept so code written against
// it reads on.
using PointLight = Light;

// Equal in every field of its table (scene/fields/fields.h).
bool operator==(const Light& a, const Light& b);
inline bool operator!=(const Light& a, const Light& b) {
  return !(a == b);
}

// Whether a light of this type is placed at a position (point and spot) or only aimed
// (directional).
inline bool has_position(LightType type) {
  return type != LightType::directional;
}

}  // namespace gloss

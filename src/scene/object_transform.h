#pragma once
// Where an object sits, applied after its type's own fields (docs/scene-format.md, "transform"):
// p' = pivot + translate + Rz Ry Rx S (p - pivot), rotations in degrees about x first. The editor's
// gizmo and numeric fields edit it; the default is the identity, which leaves an object exactly
// as its own fields make it.
#include <glm/vec3.hpp>

namespace gloss {

struct ObjectTransform {
  glm::vec3 translate{0.0f};  // world units, added last
  glm::vec3 rotate{0.0f};     // degrees about x, then y, then z (all about the pivot)
  glm::vec3 scale{1.0f};      // per axis of the object's own frame; no axis 0; a sphere's uniform
  glm::vec3 pivot{0.0f};      // world units: the object's own centre unless pivot_set
  bool pivot_set = false;     // the file (or the user) gave the pivot; else it follows the centre
};

// Equal in every field of its table (scene/fields/fields.h) and in pivot_set.
bool operator==(const ObjectTransform& a, const ObjectTransform& b);
inline bool operator!=(const ObjectTransform& a, const ObjectTransform& b) {
  return !(a == b);
}

}  // namespace gloss

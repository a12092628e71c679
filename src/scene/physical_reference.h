#pragma once
// The physical (microfacet) reference a material may be held against
// (docs/spec/physical-reference.md): a measured metal or a dielectric with a base colour, and a
// roughness. Document data only: the Phong renderer ignores it; the reference path
// (reference/reference_renderer.h) renders it and physical/phong_fit.h fits Phong to it.
#include <glm/vec3.hpp>

namespace gloss {

// What the reference is made of: one of the measured metals (physical/measured_metals.h) or a
// dielectric (F0 = 0.04 plus a Lambertian base colour). The names are the scene file's and the
// command line's, in this order.
enum class ReferenceKind { gold, silver, aluminium, copper, chromium, brass, dielectric };

inline constexpr int kReferenceKinds = 7;

// "gold" ... "dielectric"; parse returns false for any other name.
const char* to_string(ReferenceKind kind);
bool parse_reference_kind(const char* name, ReferenceKind& kind);

inline bool is_metal(ReferenceKind kind) {
  return kind != ReferenceKind::dielectric;
}

struct PhysicalReference {
  ReferenceKind kind = ReferenceKind::gold;
  glm::vec3 base{0.8f};    // dielectric's diffuse albedo, linear RGB in [0, 1]; kept (unused)
                           // for metals, so switching back to a dielectric restores it
  float roughness = 0.3f;  // perceptual roughness in (0, 1]; the GGX width is a = roughness^2
};

// Equal in every field of its table (scene/fields/fields.h).
bool operator==(const PhysicalReference& a, const PhysicalReference& b);
inline bool operator!=(const PhysicalReference& a, const PhysicalReference& b) {
  return !(a == b);
}

}  // namespace gloss

#pragma once
// A scene's environment light (docs/spec/shading.md, "Environment light"): an equirectangular
// radiance map, its intensity, its rotation about the world's up axis, and whether primary rays
// that hit nothing see it. The map is immutable and shared, as meshes are: copies of the scene
// (undo, the engine's) share it, and swapping it is a pointer change.
#include <cstdint>
#include <memory>
#include <string>

#include "base/image.h"

namespace gloss {

struct EnvironmentMap {
  // Radiance, linear RGB, every texel finite and >= 0; W x H, row 0 at the top (+y, t = 0),
  // column 0 at u = 0 (phi = -pi: straight behind a camera looking down -z).
  Image radiance;
  std::string source;  // the file it was read from, as opened
  std::uint64_t bytes() const { return radiance.pixels.size() * sizeof(glm::vec3); }
};

struct Environment {
  std::string file;  // as the scene names it (relative to the scene's folder); "" with no map
  std::shared_ptr<const EnvironmentMap> map;  // null: no environment light
  float intensity = 1.0f;                     // radiance scale, >= 0
  float rotation = 0.0f;      // degrees about +y; positive turns the map counter-clockwise
                              // seen from above
  bool as_background = true;  // primary rays that hit nothing see the map (else `background`)

  bool present() const { return map != nullptr; }
};

// Equal in every field of its table (scene/fields/fields.h), the file, and the same map.
bool operator==(const Environment& a, const Environment& b);
inline bool operator!=(const Environment& a, const Environment& b) {
  return !(a == b);
}

}  // namespace gloss

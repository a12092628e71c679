#pragma once
// The one place that decides what an edit invalidates (the edit path is widget -> command ->
// document -> change class -> renderer). Classes are ordered: a larger one includes the smaller.
#include "scene/scene.h"

namespace gloss {

enum class ChangeClass {
  none = 0,
  shade = 1,     // ka, kd, ks, ke, light colours, scene ambient, background, energy switch:
                 // recombine cached per-pixel factors, no rays
  exponent = 2,  // shininess, Phong / Blinn-Phong, which material an object uses: rebuild the
                 // per-pixel factors from cached per-sample cosines, no rays
  light = 3,     // light position, attenuation, lights added or removed, shadows switch, or a
                 // change of the render plan: shadow rays and re-shade, primary hits reused
  full = 4,      // camera, geometry, resolution, spp target, seed: progressive restart
};

const char* to_string(ChangeClass change);

ChangeClass classify_change(const Scene& before, const Scene& after);

}  // namespace gloss

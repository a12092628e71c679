#pragma once
// Opacity maps as cut-outs (docs/spec/shading.md, "Textures"): where a material's opacity map
// (its alpha, else its first channel, bilinear at level 0) is below 0.5 there is no surface, for
// primary and shadow rays alike. Embree filter functions on the geometry of every object whose
// material has one turn such hits down, so Embree goes on to the next surface along the ray (a
// sphere's far side, what lies behind); the renderers' ray code does not change.
#include <embree3/rtcore.h>

#include <memory>

#include "scene/scene.h"

namespace gloss {

// What a cut-out's filters read: the object's geometry and its opacity map.
struct CutOut {
  std::shared_ptr<const Mesh> mesh;  // triangles: the corners' (u, v); null for a sphere
  glm::vec3 centre{0.0f};            // sphere
  float radius = 1.0f;
  TextureMap map;  // the opacity map (its texture shared)
};

// The cut-out of an object, or null when its material has no opacity map.
std::unique_ptr<CutOut> make_cut_out(const Scene& scene, const Object& object);

// Embree filter functions for triangle geometry (user pointer: a CutOut), for primary and shadow
// rays.
void cut_out_triangles(const RTCFilterFunctionNArguments* args);
// For spheres: the intersection filter, and the occlusion filter, which also drops the hits a
// shadow ray cannot really have on its own sphere (self_shadow.h).
void cut_out_sphere(const RTCFilterFunctionNArguments* args);
void cut_out_sphere_occluded(const RTCFilterFunctionNArguments* args);

}  // namespace gloss

#pragma once
// The reference path of docs/spec/shading.md: the whole pipeline evaluated in a scalar type T
// (float or double), one Embree ray at a time. Embree only finds which primitive a ray hits (in
// float); the hit point, normals, camera rays, shading and accumulation are then recomputed in T,
// and shading goes through shading.h, the same functions the fast renderer calls.
// render_reference<double> at 256 spp is the reference that gloss-cli tradeoff measures every
// knob against.
#include <atomic>
#include <cstdint>
#include <optional>
#include <vector>

#include "base/image.h"
#include "reference/reference_environment.h"
#include "scene/render_settings.h"
#include "scene/scene.h"

namespace gloss {

struct ReferenceOptions {
  int spp = 0;                 // samples per pixel; 0 = scene.render.spp
  std::optional<PowMode> pow;  // unset = scene.render.pow; fast applies to T = float only
  // Per-vertex (Gouraud) shading of meshes: each corner of the hit triangle is shaded with its
  // vertex normal (flat meshes: the face normal) at the vertex's position, unshadowed; the
  // per-light diffuse and specular factors are interpolated with the hit's barycentrics and then
  // multiplied by the pixel's own shadow test. Shadows stay per pixel so that this knob measures
  // the interpolation alone (the shadows knob measures shadows). Spheres stay per pixel.
  bool gouraud = false;
  const std::atomic<bool>* cancel = nullptr;  // when it turns true the images stay incomplete
  // When set, resized to width * height and filled with 1 for pixels at a silhouette, shadow or
  // hard cone edge, 0 elsewhere: pixels whose samples, or whose 8 neighbours' first samples,
  // differ in the object hit, in a shadow test or in lying inside a hard-edged spot's cone, or,
  // within one mesh, lie on another part of it (off the tangent plane by more than 14.5
  // degrees) or, for flat meshes, on another face. These are the pixels where a hit, a shadow
  // test or a cone test can flip between precisions (spec: counted and reported, not hidden).
  std::vector<std::uint8_t>* edges = nullptr;
  // Adaptive sampling's placement (engine RenderOptions::refined): when set (width * height
  // entries), pixels marked 1 take spp stratified samples and the others one at the centre.
  const std::vector<std::uint8_t>* refined = nullptr;
  // The environment light's integrals: their error bound with shadows off, directions per hit
  // with shadows on (reference_environment.h).
  ReferenceEnvironmentOptions environment;
  // Materials that carry a physical reference (Material::reference) are shaded by it instead of
  // by Phong (docs/spec/physical-reference.md): each light adds pi f(l, v) Ld ndl att vis, in
  // double whatever T is, the microfacet lobe to the specular image and a dielectric's base to
  // the diffuse one; Ls, the energy switch and the Gouraud knob do not apply to them. Ambient
  // and emission stay ka (A_scene + sum La) and ke. Other materials are shaded as always.
  bool physical = false;
};

// Renders scene.render's size, model, shadows, energy normalisation and seed, with the fast
// renderer's sample positions (sampling.h) and camera formula (camera.h), evaluated in T. Output
// images are float. Parallel over rows (oneTBB); flush-to-zero only for T = float. Throws
// InputError for a scene that fails validate_scene, RuntimeFailure for an Embree failure.
template <class T>
TermImages render_reference(const Scene& scene, const ReferenceOptions& options = {});

extern template TermImages render_reference<float>(const Scene&, const ReferenceOptions&);
extern template TermImages render_reference<double>(const Scene&, const ReferenceOptions&);

}  // namespace gloss

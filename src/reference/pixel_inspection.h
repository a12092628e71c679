#pragma once
// What the contract computed at one pixel centre (docs/spec/shading.md), term by term and light
// by light, from the reference path in double: the editor's pixel inspector and the `inspect`
// script verb (docs/editor.md) show it. The sums are the ones render_reference<double> forms at
// one sample per pixel, so `total` is that image's pixel before its rounding to float.
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scene/render_settings.h"
#include "scene/scene.h"

namespace gloss {

// One light's factors at the pixel's hit.
struct LightBreakdown {
  LightType type = LightType::point;
  double distance = 0.0;  // d = |P_i - p|, world units (0 for a directional light: none)
  double ndl = 0.0;       // dot(n, l) before the ndl <= 0 rule (0 when d = 0)
  double cosine = 0.0;    // c of the scene's model (R . V or N . H); 0 where the light adds nothing
  double cosine_power = 0.0;  // c^alpha; 0 where c <= 0 or the light adds nothing
  double attenuation = 1.0;   // 1 / (c0 + c1 d + c2 d^2); 1 for a directional light
  double spot = 1.0;          // the cone's factor of a spot (0 outside the cone); 1 otherwise
  double visibility = 1.0;    // 0 when shadows are on and the segment to the light is blocked
  glm::dvec3 diffuse{0.0};    // kd Ld ndl att vis, 0 when ndl <= 0
  glm::dvec3 specular{0.0};   // ks Ls c^alpha att vis (times the energy factor), 0 when ndl <= 0
};

// The environment's terms at the pixel's hit (reference_environment.h): exact integrals with
// error bounds when shadows are off, estimates with standard errors when they are on.
struct EnvironmentBreakdown {
  bool present = false;    // the scene has an environment and the pixel a hit
  bool estimated = false;  // shadows on: estimates (error = standard error) not bounds
  glm::dvec3 diffuse{0.0}, specular{0.0};  // kd (1/pi) int L cos vis, ks lobe mean
  glm::dvec3 diffuse_error{0.0}, specular_error{0.0};
  glm::dvec3 unshadowed_diffuse{0.0}, unshadowed_specular{0.0};  // the same without vis
  double visibility = 1.0;  // the visible share of the irradiance (1 with shadows off)
};

// What one map gave at the pixel's hit.
struct MapReading {
  bool present = false;
  double level = 0.0;     // the mip level read (after clamping to the pyramid)
  glm::dvec4 texel{0.0};  // the filtered value (r, g, b, a)
};

struct PixelBreakdown {
  int x = 0, y = 0;           // the pixel, of the scene's render size
  int width = 0, height = 0;  // the scene's render size
  bool hit = false;           // false: the primary ray met no surface (total = background)
  int object = -1;            // index into scene.objects, -1 on a miss
  std::string object_name;    // as in the scene ("" when unnamed)
  int material = -1;          // index into scene.materials
  std::string material_name;
  ShadingModel model = ShadingModel::phong;
  double alpha = 0.0;          // the material's shininess
  double energy_factor = 1.0;  // the normalisation applied to specular (1 when off)
  glm::dvec3 position{0.0};    // p, world units
  glm::dvec3 normal{0.0};      // n, shading normal on the viewer's side
  glm::dvec3 view{0.0};        // v, unit, towards the eye
  glm::dvec3 emissive{0.0}, ambient{0.0}, diffuse{0.0}, specular{0.0};
  glm::dvec3 total{0.0};  // shading/total.h form_total of the four (background on a miss)
  std::vector<LightBreakdown> lights;  // one per scene light, in order
  EnvironmentBreakdown environment;
  // Maps (docs/spec/shading.md, "Textures"), when the material has any.
  bool textured = false;
  glm::dvec2 uv[2] = {glm::dvec2(0.0), glm::dvec2(0.0)};  // (u, v) of sets 0 and 1
  double footprint[2] = {0.0, 0.0};  // the sample's footprint in each set's (u, v) units
  MapReading maps[kMapSlots];        // by MapSlot
};

// Answers for many pixels of one scene (the editor's hover) without rebuilding the ray-tracing
// scene each time. Throws InputError for a scene that fails validate_scene, RuntimeFailure when
// Embree fails.
class PixelInspector {
 public:
  explicit PixelInspector(const Scene& scene);
  ~PixelInspector();
  PixelInspector(const PixelInspector&) = delete;
  PixelInspector& operator=(const PixelInspector&) = delete;

  // The centre of pixel (x, y) of the scene's render size (0 <= x < width, 0 <= y < height;
  // std::out_of_range otherwise), one sample, exact pow, no Gouraud knob.
  PixelBreakdown inspect(int x, int y) const;

 private:
  struct State;
  std::unique_ptr<State> m;
};

// One pixel of a scene: builds a PixelInspector and asks it once.
PixelBreakdown inspect_pixel(const Scene& scene, int x, int y);

}  // namespace gloss

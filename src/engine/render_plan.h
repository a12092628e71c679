#pragma once
// What a render has to compute, derived from the scene before any ray is traced: only the work
// the scene can see. A plan made with full = true computes everything (the test oracle).
#include <vector>

#include "scene/render_settings.h"
#include "scene/scene.h"
#include "shading/light_source.h"

namespace gloss {

struct RenderPlan {
  std::vector<int> lights;  // scene lights that reach diffuse or specular (Ld or Ls not 0)
  std::vector<bool> unit_attenuation;  // per planned light: (c0, c1, c2) == (1, 0, 0)
  // Per planned light: its type, world-space position and direction (a headlight's turned into
  // the camera's frame), cone: what the packets evaluate (shading/light_source.h).
  std::vector<LightSource<float>> sources;
  bool shadow_rays = false;  // shadows on and some object can occlude another point
  bool emissive = false;     // some material has ke != 0
  bool ambient = false;      // some ka != 0 and A_scene + sum La != 0
  bool diffuse = false;      // some kd != 0 and a planned light has Ld != 0
  bool specular = false;     // some ks != 0 and a planned light has Ls != 0
  bool spheres = false;      // some object is a sphere (its hits are refined in double)
  // The environment light reaches some kd or ks: three more slots of light factors after the
  // planned lights, one per colour channel (engine/environment/environment_lanes.cpp).
  bool environment = false;
  // The scene has an environment: the sky (the map seen where primary rays miss) is kept per
  // pixel, so turning as_background on or off only recombines.
  bool sky = false;

  // Slots of light factors per sample: the planned lights, then the environment's three.
  std::size_t slots() const { return lights.size() + (environment ? 3 : 0); }
  std::size_t environment_slot(int channel) const {
    return lights.size() + static_cast<std::size_t>(channel);
  }

  bool operator==(const RenderPlan& o) const {
    return lights == o.lights && unit_attenuation == o.unit_attenuation && sources == o.sources &&
           shadow_rays == o.shadow_rays && emissive == o.emissive && ambient == o.ambient &&
           diffuse == o.diffuse && specular == o.specular && spheres == o.spheres &&
           environment == o.environment && sky == o.sky;
  }
  bool operator!=(const RenderPlan& o) const { return !(*this == o); }
};

// full = true: every light, every term, shadow rays whenever shadows are on.
RenderPlan make_render_plan(const Scene& scene, bool full = false);

}  // namespace gloss

#pragma once
// What a render has to compute, derived from the scene before any ray is traced: only the work
// the scene can see. A plan made with full = true computes everything (the test oracle).
#include <vector>

#include "scene/render_settings.h"
#include "scene/scene.h"
#include "shading/light_source.h"

namespace gloss {

// What the materials' maps ask of a render (docs/engine.md, "Maps"): which multipliers vary per
// sample, kept per sample as texel channels in the caches, and whether maps move the shading
// normal.
struct TexturePlan {
  bool kd = false;       // some material has a diffuse map (it also multiplies ka)
  bool ka = false;       // some material has an ambient map: ka has channels of its own
  bool ks = false;       // specular maps
  bool ke = false;       // emission maps
  bool alpha = false;    // shininess maps
  bool normals = false;  // normal or bump maps
  MapFilter filter = MapFilter::trilinear;

  // Per-sample channels, in this order where present: kd (r, g, b), ka (r, g, b), ks, ke, alpha.
  // Without an ambient map of its own, ka reads kd's channels (or 1 where there are none).
  int kd_channel() const { return kd || ka ? 0 : -1; }
  int ka_channel() const { return ka ? 3 : kd_channel(); }
  int ks_channel() const { return ks ? 3 * ((kd || ka ? 1 : 0) + (ka ? 1 : 0)) : -1; }
  int ke_channel() const {
    return ke ? 3 * ((kd || ka ? 1 : 0) + (ka ? 1 : 0) + (ks ? 1 : 0)) : -1;
  }
  int alpha_channel() const {
    return alpha ? 3 * ((kd || ka ? 1 : 0) + (ka ? 1 : 0) + (ks ? 1 : 0) + (ke ? 1 : 0)) : -1;
  }
  std::size_t channels() const {
    return 3 * ((kd || ka ? 1 : 0) + (ka ? 1 : 0) + (ks ? 1 : 0) + (ke ? 1 : 0)) + (alpha ? 1 : 0);
  }
  // Whether the packets look maps up at all.
  bool any() const { return channels() > 0 || normals; }

  // The filter is left out: another filter samples the same channels again (a `texture` edit).
  bool operator==(const TexturePlan& o) const {
    return kd == o.kd && ka == o.ka && ks == o.ks && ke == o.ke && alpha == o.alpha &&
           normals == o.normals;
  }
};

// The arrays of a cache plane: light-factor slots and texel channels.
struct PlaneShape {
  std::size_t slots = 0;
  std::size_t texels = 0;
  // The last this many slots have cosines of 1 everywhere (the environment's: its lobe is in its
  // weights), so their cosine arrays are neither stored nor kept (sample_cache.h).
  std::size_t unit_cosine_slots = 0;
  PlaneShape(std::size_t s, std::size_t t = 0, std::size_t u = 0)  // NOLINT: from a count
      : slots(s), texels(t), unit_cosine_slots(u) {}
};

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

  TexturePlan textures;

  // Slots of light factors per sample: the planned lights, then the environment's three.
  std::size_t slots() const { return lights.size() + (environment ? 3 : 0); }
  PlaneShape plane_shape() const {
    return {slots(), textures.channels(), environment ? std::size_t(3) : std::size_t(0)};
  }
  std::size_t environment_slot(int channel) const {
    return lights.size() + static_cast<std::size_t>(channel);
  }

  bool operator==(const RenderPlan& o) const {
    return lights == o.lights && unit_attenuation == o.unit_attenuation && sources == o.sources &&
           shadow_rays == o.shadow_rays && emissive == o.emissive && ambient == o.ambient &&
           diffuse == o.diffuse && specular == o.specular && spheres == o.spheres &&
           environment == o.environment && sky == o.sky && textures == o.textures;
  }
  bool operator!=(const RenderPlan& o) const { return !(*this == o); }
};

// full = true: every light, every term, shadow rays whenever shadows are on.
RenderPlan make_render_plan(const Scene& scene, bool full = false);

}  // namespace gloss

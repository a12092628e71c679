#pragma once
// What an edit of the document invalidates, ordered: a larger class includes the smaller. Each
// editable field declares its class (scene/fields/fields.cpp); scene_diff.h finds the largest among
// the fields two scenes differ in, and the engine restarts at that stage.
namespace gloss {

enum class ChangeClass {
  none = 0,         // nothing the renderer computes (names, file path, display encoding)
  shade = 1,        // ka, kd, ks, ke, light colours, scene ambient, background, energy switch:
                    // recombine cached per-pixel factors, no rays
  exponent = 2,     // shininess, Phong / Blinn-Phong, pow mode, which material an object uses:
                    // rebuild the per-pixel factors from cached per-sample cosines, no rays
  environment = 3,  // the environment's map or rotation (and, under an environment, what
                    // `exponent` covers: its specular term depends on the exponent and model):
                    // the environment's factors from the cached hits, no primary rays
  texture = 4,      // a colour or shininess map swapped or its settings changed, the map
                    // filter: the maps sampled again at the cached hits, then what
                    // `environment` covers (a shininess map moves the environment's lobes), no
                    // rays
  light = 5,        // light position, attenuation, lights added or removed, shadows switch, a
                    // normal or bump map or its scale (the shading normal moves), or a change of
                    // the render plan: shadow rays and re-shade, primary hits reused
  full = 6,         // camera, geometry, resolution, spp target, seed, an opacity map (what
                    // rays hit): progressive restart
};

const char* to_string(ChangeClass change);

inline ChangeClass raise(ChangeClass a, ChangeClass b) {
  return a < b ? b : a;
}

}  // namespace gloss

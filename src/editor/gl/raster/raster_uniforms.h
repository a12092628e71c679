#pragma once
// The uniforms of the shading contract a raster program reads (shaders/raster_common.glsl,
// phong_contract.glsl): a material's constants, the scene's lights and ambient, the lights'
// shadow maps. Each program takes them when the raster renderer switches to it.
#include <vector>

#include <glad/gl.h>

#include "editor/gl/raster/shadow_maps.h"
#include "scene/scene.h"

namespace gloss {

// ka, kd, ks, ke and alpha.
void set_material_uniforms(GLuint program, const Material& m);

// Everything of the contract that is the same for every object of the frame: the ambient and
// each light (position, colours, attenuation, direction, cone).
void set_scene_uniforms(GLuint program, const Scene& scene);

// Where each light's shadow maps are and, for single maps, their views (raster_common.glsl).
void set_shadow_uniforms(GLuint program, const std::vector<LightShadow>& lights);

}  // namespace gloss

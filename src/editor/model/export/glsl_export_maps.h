#pragma once
// The maps' part of an exported shader (editor/model/export/glsl_export.h): the material's maps
// as samplers with their settings as constants, shaders/texture_lookup.glsl, and the pyramid
// levels written beside the shader as PFM files, one per level, so the host uploads exactly the
// levels gloss filters with (texture/mip_pyramid.h) and the lookups agree with the ray tracer's.
#include <string>
#include <vector>

#include "scene/scene.h"

namespace gloss {

// A GLSL float literal that reads back as the same float: 9 significant digits, and always a
// '.' or an exponent (GLSL ES 3.00 has no implicit int-to-float conversion).
std::string glsl_float(float value);

// The file of a level of a slot's map beside a shader exported to shader_path:
// STEM-SLOT_map-LLEVEL.pfm (for example teapot-diffuse_map-L0.pfm).
std::string map_level_name(const std::string& shader_path, MapSlot slot, int level);

// The declarations and lookup code for material's maps (placed before the contract; the lookup
// code comes after it, from map_lookup_part); "" for a material without maps.
// shader_path names the level files in the comments.
std::string map_declarations(const Material& material, MapFilter filter,
                             const std::string& shader_path);
// shaders/texture_lookup.glsl for a material with maps, else "".
std::string map_lookup_part(const Material& material);
// The body of main() for a material with maps: the cut-out, the frame of the hit, the maps'
// values and the contract with them.
std::string map_main_body();

// Writes the levels of every map of material beside shader_path (atomically, each a PFM of
// linear float RGB; a one-channel map as grey, an opacity map read from its alpha as that
// alpha). Returns the files written. Throws RuntimeFailure when one cannot be written.
std::vector<std::string> write_map_levels(const std::string& shader_path, const Material& material);

}  // namespace gloss

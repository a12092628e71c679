#pragma once
// "Export GLSL" (issue 12): a self-contained GLSL fragment shader for one material of the
// document under the document's lights, the shading contract of shaders/phong_contract.glsl with
// every constant filled in from the scene and a comment naming where each came from. The text
// only: no GL here (the model stays GL-free; tests/editor/gl compiles and runs the result).
//
// The host program supplies, per fragment: the world-space position and normal (`in vec3
// gloss_position, gloss_normal`) and the eye position (`uniform vec3 gloss_eye`); the shader
// writes the total to colour attachment 0 and the four terms to attachments 1..4.
#include <string>

#include "scene/scene.h"

namespace gloss {

// The fragment shader text for scene.materials[material] (GLSL 3.30 core; the header says the
// one line to change for GLSL ES 3.00 / WebGL 2). Throws std::out_of_range for a bad index.
// With an environment, the shader carries its fast path (shaders/environment.glsl) and reads
// the prefiltered levels from a sampler the host fills from the file `atlas`.
// With maps, it carries their samplers, settings and lookups (glsl_export_maps.h), naming the
// level files written beside shader_path.
std::string export_glsl(const Scene& scene, int material,
                        const std::string& atlas = "environment.pfm",
                        const std::string& shader_path = "material.glsl");

// The atlas file written beside a shader exported to shader_path: STEM-environment.pfm.
std::string environment_atlas_name(const std::string& shader_path);

// Writes export_glsl(scene, material) to path atomically (base/atomic_file.h) and, with an
// environment, its levels to environment_atlas_name(path) beside it (PFM, linear float), and the
// levels of the material's maps (glsl_export_maps.h); throws RuntimeFailure when a file cannot
// be written.
void write_glsl_export(const std::string& path, const Scene& scene, int material);

// The contract source, shaders/phong_contract.glsl, the environment's fast path,
// shaders/environment.glsl, and the maps, shaders/texture_lookup.glsl, embedded at build time.
extern const char* const kPhongContractGlsl;
extern const char* const kEnvironmentGlsl;
extern const char* const kTextureLookupGlsl;

}  // namespace gloss

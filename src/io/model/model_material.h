#pragma once
// An assimp material as a gloss Phong material (private to io; assimp stays out of public
// headers, so this takes the material through an opaque forward declaration).
#include <string>

#include "io/model/model_loader.h"
#include "scene/material.h"

struct aiMaterial;

namespace gloss {

struct NamedMaterial {
  std::string name;  // the file's name; "material<N>" when the file gives none
  Material material;
  // assimp's stand-in for "no material": AI_DEFAULT_MATERIAL_NAME, or the unnamed white one the
  // PLY and glTF 2.0 readers give parts without a material; such parts get gloss's grey default.
  bool is_default = false;
  ModelFileMaterial textures;  // the textures it names (read into maps by model_maps.h)
};

// Phong files (OBJ/MTL): Ka, Kd, Ks, Ke, Ns as written. glTF 2.0 (metallic-roughness):
// kd = base colour, ka = kd, ks = mix(0.04, base colour, metallic) * (1 - roughness) (the
// glTF reflectance at normal incidence, faded out as the surface gets rough), Ns = assimp's
// own AI_MATKEY_SHININESS for glTF, 1000 (1 - roughness)^2, ke = emissive factor; the textures
// it names are listed for model_maps.h. Keys a file lacks keep gloss's
// material defaults. Throws InputError (file = model_file, field = the material and key) for a
// colour component that is negative or not finite, or a negative or non-finite exponent.
NamedMaterial convert_material(const aiMaterial& in, unsigned index, const std::string& model_file);

// glTF 2.0 materials (not gloss's own, which carry exact constants): kd, ks and Ns replaced by
// the Phong lobe closest to the metallic-roughness lobe (physical/metal_rough_fit.h; ka = kd as
// the rule has it) where that is closer than the rule above and no metallic-roughness texture
// varies the material per texel; both errors measured, a note per material in model.notes.
void fit_metal_rough_materials(Model& model);

}  // namespace gloss

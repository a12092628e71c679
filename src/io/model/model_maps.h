#pragma once
// The maps a model file's materials name, read into their textures (docs/model-corpus.md,
// docs/scene-format.md "Maps from model files"):
// - OBJ: the MTL files its `mtllib` lines name, read by mtl_maps.h;
// - glTF 2.0: base colour (diffuse; its alpha the opacity of alpha mode MASK), emissive,
//   normal (with its scale), occlusion (the ambient map: base colour times 1 + strength (R - 1),
//   made per texel) and metallic-roughness, converted per texel by the rule the constants follow
//   (model_material.h): ks = mix(0.04, base colour, metallic) (1 - roughness) as the specular
//   map and (1 - roughness)^2 as the shininess map under alpha = 1000; samplers' wrap modes
//   (MIRRORED_REPEAT included), KHR_texture_transform, a second UV set, images inside the file.
// An image a model names that cannot be read is a warning naming it, and that map is left out:
// the model still loads. Maps gloss makes from a model, or takes from inside it, are named
// MODEL#MATERIAL/SLOT, which a scene reads back through model_map_cache.h.
#include <functional>
#include <string>
#include <vector>

#include "io/model/model_loader.h"

namespace gloss {

// Reads the maps of every material of model (loaded from path), filling model.unused and
// model.warnings with what could not be used.
void read_model_maps(const std::string& path, Model& model, const ModelOptions& options);

// The reference of a map made from or held in a model: MODEL#MATERIAL/SLOT.
std::string model_map_reference(const std::string& model, const std::string& material,
                                MapSlot slot);

// Calls rename(name, model_part) on the file name of every map of materials: a plain image's
// path (model_part false), or the MODEL of a map made from or held in a model (true; the
// reference is rebuilt around the new MODEL). A map is written only when its name changed: the
// maps are shared between copies of a scene until one changes (material.h).
void rename_map_files(std::vector<Material>& materials,
                      const std::function<void(std::string& name, bool model_part)>& rename);

// Names the maps of a model's materials as a scene names files, for the model file as the scene
// names it (model_file, relative to the scene's folder or absolute): an image named relative to
// the model's folder gets that folder in front, a map made from or held in the model
// MODEL#MATERIAL/SLOT gets model_file as its MODEL.
void name_maps_for_scene(std::vector<Material>& materials, const std::string& model_file);

// Splits a reference (false when file is a plain image path).
bool split_model_map_reference(const std::string& file, std::string& model, std::string& material,
                               MapSlot& slot);

}  // namespace gloss

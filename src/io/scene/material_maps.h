#pragma once
// The images a scene's materials name, read into textures (io/image/texture_reader.h): each
// map field that names a file but holds no texture yet is read, its path resolved against the
// scene's folder, colour maps sRGB-decoded and data maps linear, and its bytes counted against
// the memory budget before they are allocated. A map a scene names that cannot be read is an
// error naming the scene, the material's field and the map file (exit 2); a model's maps are
// the model loader's (missing ones are warnings there). A map a scene takes from a model
// (MODEL#MATERIAL/SLOT) loads that model once per scene load, through context.model_maps.
#include <cstdint>
#include <string>
#include <vector>

#include "scene/material.h"

namespace gloss {

struct ModelMapCache;  // io/model/model_map_cache.h

struct MapReadContext {
  std::string file;      // the scene (or materials) file, for messages
  std::string base_dir;  // the folder relative map paths resolve against; "": the current one
  std::uint64_t budget_bytes = 0;          // 0: the memory budget
  std::uint64_t* claimed_bytes = nullptr;  // what the scene holds so far; maps add theirs
  std::vector<std::string>* warnings = nullptr;
  // The models read so far for their maps (or placed as objects) in this scene load; null: each
  // call that names a model's map loads that model.
  ModelMapCache* model_maps = nullptr;
};

// The path a map's file names, resolved against base_dir.
std::string resolve_map_path(const std::string& file, const std::string& base_dir);

// Reads every named, unread map of material; field is the material's place ("materials.wood").
// Throws InputError (file = context.file, field = "materials.wood.diffuse_map").
void read_material_maps(Material& material, const std::string& field,
                        const MapReadContext& context);

// Reads one map (the editor's load button, a script's `material ... diffuse_map PATH`): the
// same rules, for slot. Throws InputError naming the map file.
void read_map(TextureMap& map, MapSlot slot, const MapReadContext& context);

}  // namespace gloss

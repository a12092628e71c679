#pragma once
// The "objects" entries of a scene file (docs/scene-format.md) turned into Objects with their
// world-space geometry. Material names are resolved to indices by the caller, once every object
// (and so every OBJ's MTL material) is known.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/material.h"
#include "scene/scene.h"

namespace gloss {

// The scene's materials by name; std::map keeps them in the order Scene::materials will have.
using MaterialMap = std::map<std::string, Material>;

struct ModelMapCache;  // io/model/model_map_cache.h

// Name of the grey material given to OBJ parts that have neither a scene material nor an MTL one.
inline const char* const kDefaultMaterialName = "default";

struct ObjectReadContext {
  std::string file;      // the scene file, for messages
  std::string base_dir;  // the folder relative paths resolve against; empty: the current one
  std::vector<std::string>* warnings = nullptr;
  std::vector<std::string>* notes = nullptr;  // a model's import notes (Model::notes)
  // The memory budget (base/memory_budget.h) and the geometry claimed by the objects read so far
  // (scene/memory/memory_estimate.h), both in bytes; an object that would pass the budget is
  // refused before its triangles are made where their count is known beforehand (teapots).
  std::uint64_t budget_bytes = UINT64_MAX;
  std::uint64_t* claimed_bytes = nullptr;
  // Where a model's maps are kept for the scene's materials that name them (null: not kept).
  ModelMapCache* model_maps = nullptr;
};

// An object whose material is still a name. field is the path of the entry's "material" key.
struct PendingObject {
  Object object;
  std::string material_name;
  std::string field;
};

// Refuses, before any object is read, the object whose estimated geometry (teapots from their
// tessellation; meshes count when read) takes the scene past context's budget, so 1000 teapots at
// tessellation 64 fail at once rather than after gigabytes. Values the reader would refuse are
// skipped here; the reader names them.
void claim_geometry_in_advance(const nlohmann::json& objects, const ObjectReadContext& context);

// Reads objects[index] and appends the Object(s) it makes: one, or one per OBJ part for a mesh
// without a material (which also adds its MTL materials to materials, named "<stem>/<name>").
void read_scene_object(const nlohmann::json& value, std::size_t index,
                       const ObjectReadContext& context, MaterialMap& materials,
                       std::vector<PendingObject>& out);

}  // namespace gloss

#pragma once
// The maps of the models one scene load has read, by material and slot, so that a scene naming
// several maps of one model (MODEL#MATERIAL/SLOT, model_maps.h) loads that model once: a load is
// a child-process import of all its geometry and the decoding of every map it names. Private to
// io; lives as long as one scene load.
#include <array>
#include <map>
#include <memory>
#include <string>

#include "io/model/model_loader.h"
#include "scene/material.h"

namespace gloss {

// A model's maps: per material name, the texture of each slot (null where it has none, or its
// image could not be read).
using ModelMapTable = std::map<std::string, std::array<std::shared_ptr<const Texture>, kMapSlots>>;

struct ModelMapCache {
  // The table of the model at path (as resolved; spellings of one path are one model), or null
  // when it has not been kept.
  const ModelMapTable* find(const std::string& path) const;
  // Keeps model's maps (the model loaded from path) and returns them.
  const ModelMapTable& keep(const std::string& path, const Model& model);

  int loads = 0;  // models kept: each one loaded once however many of its maps are named

 private:
  std::map<std::string, ModelMapTable> tables;
};

// The texture of material's slot in table, the maps of the model at model_path. Throws
// InputError naming the model when the material or the map is not there.
std::shared_ptr<const Texture> model_map_texture(const ModelMapTable& table,
                                                 const std::string& model_path,
                                                 const std::string& material, MapSlot slot);

}  // namespace gloss

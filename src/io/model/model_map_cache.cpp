#include "io/model/model_map_cache.h"

#include <filesystem>
#include <utility>

#include "base/error.h"

namespace gloss {

namespace {

std::string key(const std::string& path) {
  return std::filesystem::path(path).lexically_normal().string();
}

}  // namespace

const ModelMapTable* ModelMapCache::find(const std::string& path) const {
  const auto it = tables.find(key(path));
  return it == tables.end() ? nullptr : &it->second;
}

const ModelMapTable& ModelMapCache::keep(const std::string& path, const Model& model) {
  ModelMapTable table;
  for (std::size_t m = 0; m < model.materials.size(); ++m) {
    auto& slots = table[model.material_names[m]];
    for (int s = 0; s < kMapSlots; ++s) {
      slots[static_cast<std::size_t>(s)] = model.materials[m].map(static_cast<MapSlot>(s)).texture;
    }
  }
  ++loads;
  return tables[key(path)] = std::move(table);
}

std::shared_ptr<const Texture> model_map_texture(const ModelMapTable& table,
                                                 const std::string& model_path,
                                                 const std::string& material, MapSlot slot) {
  const auto it = table.find(material);
  if (it == table.end()) throw InputError(model_path, "has no material '" + material + "'");
  const auto& texture = it->second[static_cast<std::size_t>(slot)];
  if (texture) return texture;
  throw InputError(model_path, "material '" + material + "' has no " + to_string(slot) +
                                   " map (or its image cannot be read)");
}

}  // namespace gloss

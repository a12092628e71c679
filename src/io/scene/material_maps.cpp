#include "io/scene/material_maps.h"

#include <filesystem>

#include "base/error.h"
#include "base/field_path.h"
#include "base/memory_budget.h"
#include "io/image/texture_reader.h"
#include "io/model/model_map_cache.h"
#include "io/model/model_maps.h"

namespace gloss {

namespace {

// The texture a MODEL#MATERIAL/SLOT reference names, from the model's table in context's cache;
// a model not there yet is loaded, its maps read against what is left of the budget. What is
// claimed: each model's map_bytes (every map its load decoded, textures already in memory
// aside), once, when it is loaded, since the table holds them all until the scene's maps are
// read; a reference adds nothing. So while the scene loads the claim is what is held, and after
// it an upper bound (maps no material takes are freed with the cache). A model placed as an
// object was claimed by the object reader. Its geometry, freed before the next map, is not.
std::shared_ptr<const Texture> read_model_map(const std::string& model_path,
                                              const std::string& material, MapSlot slot,
                                              std::uint64_t budget_left,
                                              const MapReadContext& context) {
  ModelMapCache local;
  ModelMapCache& cache = context.model_maps != nullptr ? *context.model_maps : local;
  const ModelMapTable* table = cache.find(model_path);
  if (table == nullptr) {
    ModelOptions options;
    options.map_budget_bytes = budget_left;
    const Model model = load_model(model_path, options);
    if (context.claimed_bytes != nullptr) *context.claimed_bytes += model.map_bytes;
    table = &cache.keep(model_path, model);
  }
  return model_map_texture(*table, model_path, material, slot);
}

}  // namespace

std::string resolve_map_path(const std::string& file, const std::string& base_dir) {
  const std::filesystem::path path(file);
  if (path.is_absolute() || base_dir.empty()) return path.string();
  return (std::filesystem::path(base_dir) / path).string();
}

void read_map(TextureMap& map, MapSlot slot, const MapReadContext& context) {
  if (!map.named() || map.present()) return;
  const std::uint64_t budget =
      context.budget_bytes > 0 ? context.budget_bytes : memory_budget_bytes();
  const std::uint64_t claimed = context.claimed_bytes != nullptr ? *context.claimed_bytes : 0;
  if (claimed >= budget) {
    throw InputError(map.file,
                     "no memory budget is left for this map (" + memory_budget_text() + ")");
  }
  std::string model, material;
  MapSlot model_slot;
  if (split_model_map_reference(map.file, model, material, model_slot)) {
    map.texture = read_model_map(resolve_map_path(model, context.base_dir), material, model_slot,
                                 budget - claimed, context);
    return;
  }
  bool cached = false;
  map.texture = read_texture(resolve_map_path(map.file, context.base_dir),
                             is_colour_map(slot) ? ImageData::colour : ImageData::linear,
                             budget - claimed, &cached);
  if (context.claimed_bytes != nullptr && !cached) *context.claimed_bytes += map.texture->bytes();
}

void read_material_maps(Material& material, const std::string& field,
                        const MapReadContext& context) {
  for (int s = 0; s < kMapSlots; ++s) {
    const auto slot = static_cast<MapSlot>(s);
    try {
      read_map(material.map(slot), slot, context);
    } catch (const InputError& error) {
      // One line naming the scene, the material's field and the map (error.what() names it).
      fail_field(context.file, child_path(field, map_key(slot)), error.what());
    }
  }
}

}  // namespace gloss

#include "io/scene/material_maps.h"

#include <filesystem>

#include "base/error.h"
#include "base/field_path.h"
#include "base/memory_budget.h"
#include "io/image/texture_reader.h"
#include "io/model/model_maps.h"

namespace gloss {

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
  bool cached = false;
  if (split_model_map_reference(map.file, model, material, model_slot)) {
    map.texture = model_map_texture(resolve_map_path(model, context.base_dir), material, model_slot,
                                    budget - claimed);
  } else {
    map.texture = read_texture(resolve_map_path(map.file, context.base_dir),
                               is_colour_map(slot) ? ImageData::colour : ImageData::linear,
                               budget - claimed, &cached);
  }
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

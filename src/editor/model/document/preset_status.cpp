#include "editor/model/document/preset_status.h"

#include "io/material/preset_table.h"

namespace gloss {

bool preset_modified(const Material& material) {
  if (material.preset.empty()) return false;
  const Preset* preset = find_preset(material.preset);
  if (preset == nullptr) return false;
  const Material& p = preset->material;
  return material.ambient != p.ambient || material.diffuse != p.diffuse ||
         material.specular != p.specular || material.emission != p.emission ||
         material.shininess != p.shininess;
}

std::string preset_status(const Material& material) {
  if (material.preset.empty()) return "";
  return preset_modified(material) ? material.preset + " (modified)" : material.preset;
}

}  // namespace gloss

#include "editor/model/view/lobe_overlay.h"

#include "io/material/preset_table.h"

namespace gloss {

std::optional<OverlayMaterial> lobe_overlay_material(const ViewSettings& view, const Scene& scene,
                                                     int object, const Snapshot* snapshot) {
  switch (view.lobe_overlay) {
    case LobeOverlay::none:
      return std::nullopt;
    case LobeOverlay::snapshot: {
      if (snapshot == nullptr || object < 0 ||
          object >= static_cast<int>(snapshot->scene.objects.size())) {
        return std::nullopt;
      }
      const int m = snapshot->scene.objects[static_cast<std::size_t>(object)].material;
      const std::string name = static_cast<std::size_t>(m) < snapshot->scene.material_names.size()
                                   ? snapshot->scene.material_names[static_cast<std::size_t>(m)]
                                   : "#" + std::to_string(m);
      return OverlayMaterial{snapshot->scene.materials[static_cast<std::size_t>(m)],
                             snapshot->label + ": " + name};
    }
    case LobeOverlay::material:
      for (std::size_t i = 0; i < scene.material_names.size() && i < scene.materials.size(); ++i) {
        if (scene.material_names[i] == view.lobe_overlay_name) {
          return OverlayMaterial{scene.materials[i], "material '" + view.lobe_overlay_name + "'"};
        }
      }
      return std::nullopt;
    case LobeOverlay::preset:
      if (const Preset* p = find_preset(view.lobe_overlay_name)) {
        return OverlayMaterial{p->material, "preset '" + p->name + "'"};
      }
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace gloss

#pragma once
// The lobe view's second material (ViewSettings::lobe_overlay): which material it is and what
// the view calls it, or nothing when none is chosen or the choice names nothing (a snapshot not
// taken, a material renamed away).
#include <optional>
#include <string>

#include "editor/model/view/ab_compare.h"
#include "editor/model/view/view_settings.h"
#include "scene/scene.h"

namespace gloss {

struct OverlayMaterial {
  Material material;
  std::string label;  // "snapshot 2: gold", "material 'silver'", "preset 'emerald'"
};

// object: the selected object (the snapshot's overlay is its material in the snapshot).
std::optional<OverlayMaterial> lobe_overlay_material(const ViewSettings& view, const Scene& scene,
                                                     int object, const Snapshot* snapshot);

}  // namespace gloss

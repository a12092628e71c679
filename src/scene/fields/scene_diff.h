#pragma once
// The one comparison of two versions of the document: what differs, and what that invalidates.
// The editor's command layer asks whether anything changed (undo steps, the modified flag), the
// engine what to recompute (engine/change_class.h) and whether its Embree scene still holds.
#include "scene/fields/change.h"
#include "scene/scene.h"

namespace gloss {

struct SceneDiff {
  ChangeClass change = ChangeClass::none;  // the largest class among the fields that differ
  bool geometry = false;                   // object shapes differ: a new Embree scene
  bool any = false;  // anything differs, names, presets, shape parameters and the path included
};

// Fields are compared through their tables (scene/fields/fields.h); objects by type, shape and
// material; meshes by identity (commands never modify a mesh in place, they replace objects).
SceneDiff diff_scenes(const Scene& before, const Scene& after);

}  // namespace gloss

#pragma once
// The one place that decides what an edit invalidates (the edit path is widget -> command ->
// document -> change class -> renderer): the largest change class among the fields that differ
// (scene/fields/scene_diff.h), raised to `light` when the render plan differs.
#include "scene/fields/change.h"
#include "scene/fields/scene_diff.h"
#include "scene/scene.h"

namespace gloss {

// none only when nothing at all differs; a change of names or paths alone is `shade` (nothing
// to recompute, but a new version of the document to publish).
ChangeClass classify_change(const Scene& before, const Scene& after);
// The same from their diff_scenes, for a caller that needs the diff too.
ChangeClass classify_change(const Scene& before, const Scene& after, const SceneDiff& diff);

}  // namespace gloss

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

// Whether an edit of class `change` from before to after changes the sky (the map seen where
// primary rays miss, environment/environment_stage.h): it follows the camera and the samples
// (`full`), the environment's map (another, none or a first one) and its rotation. Its intensity
// and as_background are applied as the terms are recombined, and every other edit keeps the
// primary rays: those keep the sky, whatever their class (a `texture` or `light` edit too).
bool changes_sky(const Scene& before, const Scene& after, ChangeClass change);

}  // namespace gloss

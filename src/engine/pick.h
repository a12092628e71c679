#pragma once
// Which object is under a point of the image: the editor's click-to-select.
#include "scene/scene.h"

namespace gloss {

// Object index hit by the primary ray through image position (px, py) in pixels of a
// width x height view of scene.camera (pixel centres at +0.5), or -1 for none.
int pick_object(const Scene& scene, int width, int height, float px, float py);

}  // namespace gloss

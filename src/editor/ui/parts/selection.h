#pragma once
// What the user has selected. Not part of the document (not undone, not saved but in the
// recovery file): panels, the viewport's clicks and scripts' `select` set it directly.

namespace gloss {

struct Selection {
  int object = 0;  // index into scene.objects; readers clamp it to the objects there are
  int light = 0;   // index into scene.lights; likewise
};

}  // namespace gloss

#pragma once
// One-shot rendering: scene in, term images out, at scene.render's size, spp and model.
#include "base/image.h"
#include "scene/scene.h"

namespace gloss {

struct RenderOptions {
  bool full_plan = false;  // compute everything, ignoring the render plan (the plan's oracle)
  bool terms = true;       // fill the four term images; false: total only
};

// Renders with all worker threads of the process (oneTBB). Throws InputError for a scene that
// fails validate_scene, RuntimeFailure for an Embree failure.
TermImages render(const Scene& scene, const RenderOptions& options = {});

}  // namespace gloss

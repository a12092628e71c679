#pragma once
// One-shot rendering: scene in, term images out, at scene.render's size, spp and model.
#include <cstdint>
#include <vector>

#include "base/image.h"
#include "scene/scene.h"

namespace gloss {

struct RenderOptions {
  bool full_plan = false;  // compute everything, ignoring the render plan (the plan's oracle)
  bool terms = true;       // fill the four term images; false: total only
  // Adaptive sampling (spp > 1, sampling "adaptive"), pixels as y * width + x, ascending.
  // placement: when set, the pixels to refine instead of the rule's choice (an earlier frame's,
  // to reproduce it); refined: when set, receives the pixels refined.
  const std::vector<std::uint32_t>* placement = nullptr;
  std::vector<std::uint32_t>* refined = nullptr;
};

// Renders with all worker threads of the process (oneTBB). Throws InputError for a scene that
// fails validate_scene, RuntimeFailure for an Embree failure.
TermImages render(const Scene& scene, const RenderOptions& options = {});

}  // namespace gloss

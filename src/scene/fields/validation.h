#pragma once
// The checks a render needs, on a Scene however it was made (loaded, edited, or overridden by
// gloss-cli options). Fields are named as in the scene file.
#include <string>

#include "scene/memory/memory_estimate.h"
#include "scene/scene.h"

namespace gloss {

// Checks everything a render needs (sizes, spp, camera, colours, attenuation) and throws
// InputError naming the file and the field. The scene loader calls it; gloss-cli calls it again
// after applying its overrides; the renderers call it before they allocate. The memory the scene
// needs (its geometry and its render, with samples held as `samples` says) must fit the budget
// of base/memory_budget.h.
void validate_scene(const Scene& scene, SampleMemory samples = SampleMemory::banded);

// The checks of one material (a materials file, an MTL file), named under field.
void validate_material(const std::string& file, const std::string& field, const Material& material);

}  // namespace gloss

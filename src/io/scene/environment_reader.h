#pragma once
// An environment map file (docs/spec/shading.md, "Environment light") read into the scene's
// EnvironmentMap: any image io/image/image_reader.h reads, as colour data (HDR and EXR are
// linear; an 8- or 16-bit PNG is sRGB-decoded unless the file says it is linear), grey spread to
// RGB, alpha dropped. Lossy EXR compression (DWAB) leaves samples slightly below 0: they become
// 0, with a warning. The scene loader and the editor's Environment panel read maps through it.
#include <memory>
#include <string>
#include <vector>

#include "scene/environment.h"

namespace gloss {

// What one texel of a map costs besides its decoded samples: the map itself (12 bytes) and the
// engine's tables for it (scene/memory/memory_estimate.h, environment_bytes).
std::uint64_t environment_extra_bytes_per_texel();

// Reads path against budget_bytes (0: the memory budget) already less what the scene holds
// besides. Throws InputError naming path; appends warnings (negative samples set to 0).
std::shared_ptr<const EnvironmentMap> read_environment_map(
    const std::string& path, std::uint64_t budget_bytes = 0,
    std::vector<std::string>* warnings = nullptr);

}  // namespace gloss

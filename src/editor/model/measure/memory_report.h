#pragma once
// The `memory` script line: the process's resident memory beside what the editor can account
// for (docs/editor.md, "Memory"). The engine's caches are not listed: they are what remains of
// heap_in_use once these are taken away.
#include <cstdint>
#include <string>

#include "editor/model/document/command_layer.h"

namespace gloss {

// What the window holds, in bytes (0 without a display).
struct ViewMemory {
  std::uint64_t frames = 0;    // published frames held for display (their images)
  std::uint64_t textures = 0;  // viewport textures and the off-screen target
  std::uint64_t swatches = 0;  // preset swatch textures
};

// "rss_mb=... peak_rss_mb=... heap_in_use_mb=... heap_free_mb=... history_kb=... steps=...
// frames_mb=... textures_mb=... swatches_kb=..."
std::string memory_text(const CommandLayer& layer, const ViewMemory& view);

}  // namespace gloss

#include "editor/model/measure/memory_report.h"

#include <cstdio>

#include "base/process_memory.h"

namespace gloss {

std::string memory_text(const CommandLayer& layer, const ViewMemory& view) {
  const ProcessMemory m = read_process_memory();
  constexpr double kMB = 1024.0 * 1024.0;
  char text[512];
  std::snprintf(text, sizeof text,
                "rss_mb=%.1f peak_rss_mb=%.1f heap_in_use_mb=%.1f heap_free_mb=%.1f "
                "history_kb=%.1f steps=%zu frames_mb=%.1f textures_mb=%.1f swatches_kb=%.1f",
                m.resident / kMB, m.peak_resident / kMB, m.heap_in_use / kMB, m.heap_free / kMB,
                layer.history_bytes() / 1024.0, layer.undo_count() + layer.redo_count(),
                view.frames / kMB, view.textures / kMB, view.swatches / 1024.0);
  return text;
}

}  // namespace gloss

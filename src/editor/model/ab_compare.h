#pragma once
// What the A/B view compares: the document as Phong against Blinn-Phong (the exponent rule of
// document.h applied when keep_highlight_size), or a snapshot of an earlier document against the
// live one (before/after an edit, two presets). Both sides are rendered by the same renderer at
// the same size and shown with the same heat map (heat_map.h) and scale.
#include <cstdint>
#include <string>

#include "editor/model/view_settings.h"
#include "scene/scene.h"

namespace gloss {

// The document as it was when the user pressed Snapshot. Kept as a document rather than as
// pixels so that the A side renders at whatever size the viewport's pane has now, with the
// same sampling as the live side: an unchanged document gives a difference of exactly 0.
struct Snapshot {
  Scene scene;
  std::uint64_t revision = 0;  // the command layer's revision it was taken at
  std::string label;           // "snapshot 1", shown on the A pane
};

struct AbScenes {
  Scene a, b;
};

// The two documents the A/B view renders for source. snapshot may be null only for
// AbSource::models; a null snapshot with AbSource::snapshot compares the document with itself.
AbScenes ab_scenes(const Scene& document, AbSource source, const Snapshot* snapshot,
                   bool keep_highlight_size);

// The labels of the A and B panes.
std::string ab_label_a(AbSource source, const Snapshot* snapshot);
std::string ab_label_b(AbSource source, bool keep_highlight_size);

}  // namespace gloss

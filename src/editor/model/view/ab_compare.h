#pragma once
// What the A/B view compares: the document as Phong against Blinn-Phong (the exponent rule of
// document.h applied when keep_highlight_size), a snapshot of an earlier document against the
// live one (before/after an edit, two presets), the ray tracer against the raster path on the
// same document (cpu_gl), the raster path per pixel against per vertex (pixel_vertex), or the
// material against its physical reference (reference: B renders the materials that carry one by
// the reference path's physical option, docs/spec/physical-reference.md). Both
// sides are rendered at the same size and shown with the same heat map (heat_map.h) and scale;
// ab_sides says which renderer draws each.
#include <cstdint>
#include <string>

#include "editor/model/view/view_settings.h"
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

// The renderer of one side: the ray tracer (progressive, the document's spp), the raster path
// at the given shading frequency (one sample per pixel), or the physical reference (the
// reference path in double with ReferenceOptions::physical, one sample per pixel).
struct AbSide {
  bool raster = false;
  ShadingFrequency shading = ShadingFrequency::pixel;
  bool physical = false;
  bool operator==(const AbSide& o) const {
    return raster == o.raster && shading == o.shading && physical == o.physical;
  }
};
struct AbSides {
  AbSide a, b;
};

// models and snapshot: both sides on the viewport's renderer (raster: whether the raster path
// draws the viewport now, shading its frequency). cpu_gl: A the ray tracer, B the raster path at
// shading. pixel_vertex: A raster per pixel, B raster per vertex. reference: A the ray tracer,
// B the physical reference.
AbSides ab_sides(AbSource source, bool raster, ShadingFrequency shading);

// The two documents the A/B view renders for source. cpu_gl: A is the document at 1 spp (the
// pixel centre, where the raster path samples too), B the document. pixel_vertex: the document
// twice. reference: the document twice at 1 spp (the reference side renders pixel centres).
// A null snapshot with AbSource::snapshot compares the document with itself.
AbScenes ab_scenes(const Scene& document, AbSource source, const Snapshot* snapshot,
                   bool keep_highlight_size);

// The labels of the A and B panes. shading: the raster path's frequency (cpu_gl's B side).
std::string ab_label_a(AbSource source, const Snapshot* snapshot);
std::string ab_label_b(AbSource source, bool keep_highlight_size,
                       ShadingFrequency shading = ShadingFrequency::pixel);

}  // namespace gloss

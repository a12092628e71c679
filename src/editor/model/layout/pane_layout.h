#pragma once
// How the viewport's images are arranged in its area (editor/ui/viewport draws them there).
//   - render, one term: one pane in the document's aspect (the render size exports render at),
//     centred: what you see is what an export holds;
//   - terms: 2 x 2, 4 in a row or 4 in a column; A/B: A, B and the heat map in a row or a column
//     with the legend to the right or below, or 2 x 2 with the legend in the fourth cell. These
//     panes fill the viewport (no empty bands): each is a cell of the grid, and shows the scene
//     with more of it around the document's frame (overscan_camera in camera_controller.h);
//     `frames` is where the document's own frame lies in each pane. The arrangement chosen is
//     the one whose frames are largest.
// Pixels, y down.
#include "editor/model/layout/panel_layout.h"
#include "editor/model/view/view_settings.h"

namespace gloss {

// The legend's room: beside the images (right) or under them (below), pixels.
constexpr float kLegendWidth = 210.0f;
constexpr float kLegendHeight = 112.0f;

struct PaneArrangement {
  int count = 1;         // panes: 1, 4 (terms) or 3 (A/B: A, B, heat map)
  LayoutRect panes[4];   // in order: terms emissive + ambient, diffuse, specular, total
  LayoutRect frames[4];  // the document's frame (its aspect, centred) in each pane
  LayoutRect legend;     // A/B's legend; zero-sized for the other views
  int columns = 1, rows = 1;
  bool fill = false;  // panes are grid cells, wider or taller than the document's aspect
};

// The panes of mode in area for a document of aspect width / height (> 0). Sizes are whole
// pixels; panes touch.
PaneArrangement arrange_panes(ViewMode mode, const LayoutRect& area, float aspect);

// The share of area the panes and the legend leave empty, 0..1 (the bands around them).
float empty_share(const PaneArrangement& arrangement, const LayoutRect& area);

}  // namespace gloss

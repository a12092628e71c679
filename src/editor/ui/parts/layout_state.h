#pragma once
// Where the window's panels sit: the sizes the user dragged the splitters to (layout.cpp draws
// the panels from them).

namespace gloss {

struct LayoutState {
  // Side panels, dragged by the splitters at their inner edges (screen pixels; 0: the default
  // share of the window). lights_share: the Lights panel's part of the right column's height.
  float left_width = 0.0f, right_width = 0.0f, lights_share = 0.5f;
  // The Material panel's part of the left column's height (the Reference panel has the rest).
  float material_share = 0.66f;
};

}  // namespace gloss

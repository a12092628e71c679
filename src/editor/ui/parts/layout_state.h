#pragma once
// Where the window's panels sit: the sizes the user dragged the splitters to, the collapsed
// panels, the maximised viewport (editor/model/layout/panel_layout.h has the rules; layout.cpp
// draws the panels from them), and the layout of the last frame (the script's `layout` line).
#include "editor/model/layout/panel_layout.h"

namespace gloss {

struct LayoutState {
  PanelChoices panels;
  PanelLayout last;  // as drawn in the newest frame
};

}  // namespace gloss

#pragma once
// Small widgets shared by the panels (Dear ImGui 1.86 has no SeparatorText).
#include <imgui.h>

namespace gloss {

// A section heading: a gap, the title in the disabled colour, a rule.
inline void section_title(const char* title) {
  ImGui::Spacing();
  ImGui::TextDisabled("%s", title);
  ImGui::Separator();
}

}  // namespace gloss

#include "editor/ui/panels/field_widgets.h"

namespace gloss {

bool colour_widget(const char* label, glm::vec3& colour, bool linked) {
  constexpr ImGuiColorEditFlags kFlags =
      ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR | ImGuiColorEditFlags_DisplayRGB;
  const glm::vec3 before = colour;
  if (!ImGui::ColorEdit3(label, &colour.x, kFlags)) return false;
  colour = glm::max(colour, glm::vec3(0.0f));
  int moved = -1, moved_count = 0;
  for (int c = 0; c < 3; ++c) {
    if (colour[c] != before[c]) {
      moved = c;
      ++moved_count;
    }
  }
  if (linked && moved_count == 1) {
    if (before[moved] > 0.0f) {
      colour = before * (colour[moved] / before[moved]);
    } else {
      colour = glm::max(before + glm::vec3(colour[moved] - before[moved]), glm::vec3(0.0f));
    }
  }
  return colour != before;
}

}  // namespace gloss

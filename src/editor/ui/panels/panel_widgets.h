#pragma once
// Small widgets shared by the panels (Dear ImGui 1.86 has no SeparatorText), and the helpers that
// keep a narrow panel's rows inside it.
#include <algorithm>

#include <imgui.h>

namespace gloss {

// A section heading: a gap, the title in the disabled colour, a rule.
inline void section_title(const char* title) {
  ImGui::Spacing();
  ImGui::TextDisabled("%s", title);
  ImGui::Separator();
}

// A note in the disabled colour, wrapped at the window's edge instead of cut there.
inline void disabled_text_wrapped(const char* text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", text);
  ImGui::PopStyleColor();
}

// The width of a radio button or checkbox with label: the box, the gap, the text.
inline float toggle_width(const char* label) {
  return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x +
         ImGui::CalcTextSize(label, nullptr, true).x;
}

// On this line when a widget `width` pixels wide still fits in the window, else on the next: a
// row of radio buttons wraps in a narrow panel instead of running past its edge.
inline void same_line_if_fits(float width) {
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  ImGui::SameLine();
  if (ImGui::GetCursorScreenPos().x + width > right) ImGui::NewLine();
}

// The room a panel leaves its widgets' labels: up to `most` pixels, less in a narrow panel (at
// most 36% of its width), so the fields keep most of it.
inline float label_room(float most) {
  return std::min(most, 0.36f * ImGui::GetContentRegionAvail().x);
}

}  // namespace gloss

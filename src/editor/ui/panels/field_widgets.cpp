#include "editor/ui/panels/field_widgets.h"

#include <imgui_internal.h>

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

bool log_drag_widget(const char* label, float& value, float floor, float lo, float hi) {
  // ImGui's drag with a speed too small to move the value: it gives the frame, the label,
  // Ctrl+click typing and the active state; the value of a mouse drag is set here instead.
  const ImGuiSliderFlags flags = ImGuiSliderFlags_NoRoundToFormat | ImGuiSliderFlags_AlwaysClamp;
  float shown = value;
  bool changed = ImGui::DragFloat(label, &shown, 1e-30f, lo, hi, "%.4g", flags);
  const ImGuiID id = ImGui::GetItemID();
  ImGuiStorage* storage = ImGui::GetStateStorage();
  // What the drag measures from: the value and mouse x where it (or its modifier) started.
  const ImGuiID start_key = id + 1, base_key = id + 2, step_key = id + 3;
  const ImGuiIO& io = ImGui::GetIO();
  const float per_pixel = log_drag_per_pixel(io.KeyShift, io.KeyAlt);
  if (ImGui::IsItemActivated() ||
      (ImGui::IsItemActive() && storage->GetFloat(step_key, per_pixel) != per_pixel)) {
    storage->SetFloat(start_key, value);
    storage->SetFloat(base_key, io.MousePos.x);
    storage->SetFloat(step_key, per_pixel);  // a modifier pressed mid-drag starts from here
  }
  const bool typing = ImGui::TempInputIsActive(id);
  if (ImGui::IsItemActive() && !typing && io.MouseDown[ImGuiMouseButton_Left]) {
    shown = log_drag_value(storage->GetFloat(start_key, value),
                           io.MousePos.x - storage->GetFloat(base_key, io.MousePos.x), per_pixel,
                           floor, lo, hi);
    changed = shown != value;
  }
  if (!changed) return false;
  value = shown;
  return true;
}

}  // namespace gloss

#pragma once
// One Dear ImGui widget per field kind (scene/fields/field.h), so a panel shows a table's fields by
// iterating over it: colour editors for colours, drags for vectors, sliders for numbers and whole
// numbers, checkboxes for flags, radio buttons for choices; the field's help is the tooltip. The
// widget edits a copy of the struct; the panel turns the change into a command (field_command).
#include <algorithm>

#include <imgui.h>
#include <glm/common.hpp>

#include "editor/model/view/log_drag.h"
#include "editor/ui/panels/panel_widgets.h"
#include "scene/fields/field.h"

namespace gloss {

// With linked channels a change of one channel scales the others by the same factor (or shifts
// them by the same amount from zero), keeping the hue. Components stay >= 0.
bool colour_widget(const char* label, glm::vec3& colour, bool linked);

// A logarithmic drag (editor/model/view/log_drag.h): the value follows the mouse's distance from
// the press, 1% per pixel (Shift 10%, Alt 0.1%), so it returns to its start with the mouse; no
// jump on press; Ctrl+click types a value. floor: the speed at 0, value units per pixel.
bool log_drag_widget(const char* label, float& value, float floor, float lo, float hi);

// Draws the widget of one field of value and applies an edit to value; true when it changed.
// label: shown instead of the field's own label (the exponent's follows the shading model).
template <class S>
bool field_widget(const Field<S>& field, S& value, bool link_channels = false,
                  const char* label = nullptr) {
  if (label == nullptr) label = field.label;
  FieldValue v = field.get(value);
  const FieldValue before = v;
  const float lo = static_cast<float>(field.ui_min), hi = static_cast<float>(field.ui_max);
  switch (field.kind) {
    case FieldKind::colour:
      colour_widget(label, v.v, link_channels);
      break;
    case FieldKind::vector:
      // A drag of the full range over about 2000 pixels; Ctrl+click types a value.
      ImGui::DragFloat3(label, &v.v.x, std::max((hi - lo) / 2e3f, 1e-3f), lo, hi, "%.3f");
      v.v = glm::clamp(v.v, glm::vec3(static_cast<float>(field.min)),
                       glm::vec3(static_cast<float>(field.max)));
      break;
    case FieldKind::number: {
      float x = static_cast<float>(v.x);
      if (field.ui_log) {
        if (log_drag_widget(label, x, std::max((hi - lo) * 1e-6f, 1e-3f), lo, hi)) v.x = x;
      } else if (ImGui::SliderFloat(label, &x, lo, hi, "%.3g", ImGuiSliderFlags_NoRoundToFormat)) {
        v.x = x;
      }
      break;
    }
    case FieldKind::whole: {
      int x = static_cast<int>(v.x);
      const ImGuiSliderFlags flags = field.ui_log ? ImGuiSliderFlags_Logarithmic : 0;
      if (ImGui::SliderInt(label, &x, static_cast<int>(lo), static_cast<int>(hi), "%d", flags)) {
        v.x = std::clamp(static_cast<double>(x), field.min, field.max);
      }
      break;
    }
    case FieldKind::flag: {
      bool on = v.x != 0.0;
      if (ImGui::Checkbox(label, &on)) v.x = on ? 1.0 : 0.0;
      break;
    }
    case FieldKind::map:  // the material panel's map slots draw these (map_slots.cpp)
      return false;
    case FieldKind::choice: {
      int index = static_cast<int>(v.x);
      ImGui::TextUnformatted(label);
      for (int i = 0; i < static_cast<int>(field.choices.size()); ++i) {
        same_line_if_fits(toggle_width(field.choices[static_cast<std::size_t>(i)]));
        ImGui::PushID(i);
        ImGui::RadioButton(field.choices[static_cast<std::size_t>(i)], &index, i);
        ImGui::PopID();
      }
      v.x = index;
      break;
    }
  }
  if (field.help[0] != '\0' && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", field.help);
  if (v == before) return false;
  field.set(value, v);
  return true;
}

}  // namespace gloss

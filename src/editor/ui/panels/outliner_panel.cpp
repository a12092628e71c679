// The Outliner: every object of the scene in a list (a filter, click to select, Ctrl+click to add
// or remove, Shift+click for a range, double-click to rename, the box to hide or show, a context
// menu), buttons that add, duplicate, delete, hide, solo and frame, and the selected object's
// name, material and transform as numeric fields from the document's tables. Every change is a
// command; a drag of a field is one undo step.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "base/text/ascii.h"
#include "editor/model/document/new_objects.h"
#include "editor/model/view/camera_controller.h"
#include "editor/ui/file_browser.h"
#include "editor/ui/panels/field_widgets.h"
#include "editor/ui/panels/panel_state.h"
#include "editor/ui/panels/panel_widgets.h"
#include "editor/ui/panels/panels.h"
#include "editor/ui/parts/commands.h"
#include "editor/ui/parts/selection.h"
#include "scene/geometry/placement.h"

namespace gloss {

namespace {

bool contains_ignoring_case(const std::string& text, const std::string& part) {
  if (part.empty()) return true;
  return std::search(text.begin(), text.end(), part.begin(), part.end(),
                     [](char a, char b) { return ascii_lower(a) == ascii_lower(b); }) != text.end();
}

// A click on row i of the listed objects (shown, in list order).
void click_row(Selection& selection, OutlinerState& state, const std::vector<int>& shown, int count,
               int i) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.KeyShift && state.anchor >= 0) {
    const auto a = std::find(shown.begin(), shown.end(), state.anchor);
    const auto b = std::find(shown.begin(), shown.end(), i);
    if (a != shown.end() && b != shown.end()) {
      std::vector<int> range(std::min(a, b), std::max(a, b) + 1);
      std::vector<int> all = io.KeyCtrl ? selected_objects(selection, count) : std::vector<int>{};
      all.insert(all.end(), range.begin(), range.end());
      all.erase(std::remove(all.begin(), all.end(), i), all.end());
      all.insert(all.begin(), i);  // the clicked one is primary
      select_all_of(selection, all);
      return;
    }
  }
  state.anchor = i;
  if (io.KeyCtrl) {
    std::vector<int> all = selected_objects(selection, count);
    const auto it = std::find(all.begin(), all.end(), i);
    if (it != all.end() && all.size() > 1) {
      all.erase(it);
      select_all_of(selection, all);
    } else if (it == all.end()) {
      all.insert(all.begin(), i);
      select_all_of(selection, all);
    }
    return;
  }
  select_only(selection, i);
}

void add_menu_items(Commands& commands, Selection& selection, FileBrowser& browser) {
  const Scene& scene = commands.scene();
  const ObjectType types[4] = {ObjectType::sphere, ObjectType::quad, ObjectType::box,
                               ObjectType::teapot};
  const char* labels[4] = {"Sphere", "Quad", "Box", "Teapot"};
  for (int t = 0; t < 4; ++t) {
    if (!ImGui::MenuItem(labels[t])) continue;
    const int first = static_cast<int>(scene.objects.size());
    if (commands.execute(primitive_objects(scene, types[t]))) select_only(selection, first);
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Model from a file...")) {
    browser.start(BrowsePurpose::add_model, scene.path, "");
  }
}

// What Rename, Duplicate ... do to the selected objects (the buttons, the context menu).
void selection_items(Commands& commands, Selection& selection, OutlinerState& state, bool as_menu) {
  const Scene& scene = commands.scene();
  const int count = static_cast<int>(scene.objects.size());
  const std::vector<int> objects = selected_objects(selection, count);
  if (objects.empty()) return;
  const bool any_hidden =
      std::any_of(objects.begin(), objects.end(), [&](int i) { return scene.objects[i].hidden; });
  auto item = [&](const char* label, const char* shortcut, const char* tip) {
    if (as_menu) return ImGui::MenuItem(label, shortcut);
    // On the same row while it fits, else on the next.
    const ImGuiStyle& style = ImGui::GetStyle();
    const float width = ImGui::CalcTextSize(label).x + 2.0f * style.FramePadding.x;
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (ImGui::GetItemRectMax().x + style.ItemSpacing.x + width <= right) ImGui::SameLine();
    const bool pressed = ImGui::SmallButton(label);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s (%s)", tip, shortcut);
    return pressed;
  };
  if (as_menu && ImGui::MenuItem("Rename", "F2")) {
    state.renaming = selection.object;
    state.rename_text = scene.objects[static_cast<std::size_t>(selection.object)].name;
    state.focus_rename = true;
  }
  if (item("Duplicate", "Ctrl+D", "copies beside the originals, sharing their materials")) {
    if (commands.execute(DuplicateObjects{objects})) {
      std::vector<int> copies;
      for (std::size_t k = 0; k < objects.size(); ++k) copies.push_back(count + int(k));
      select_all_of(selection, copies);
    }
  }
  if (item("Delete", "Del", "delete the selected objects (undo brings them back)")) {
    if (commands.execute(DeleteObjects{objects})) select_only(selection, objects.front() - 1);
  }
  if (item(any_hidden ? "Show" : "Hide", "H", "hidden objects are not rendered, cast no shadow")) {
    commands.execute(SetHidden{objects, !any_hidden});
  }
  if (item("Solo", "Shift+H", "show only the selected objects")) {
    commands.execute(SoloObjects{objects});
  }
  if (item("Frame", "F", "turn the camera to the selection and fit it in the view")) {
    frame_selection(commands, selection);
  }
}

void draw_row(Commands& commands, Selection& selection, OutlinerState& state,
              const std::vector<int>& shown, const std::vector<int>& selected, int i) {
  const Scene& scene = commands.scene();
  const Object o = scene.objects[static_cast<std::size_t>(i)];  // a copy: commands replace it
  ImGui::PushID(i);
  bool visible = !o.hidden;
  if (ImGui::Checkbox("##visible", &visible)) {
    Object edited = o;  // the field of the object table (scene/fields/fields.h)
    edited.hidden = !visible;
    if (auto command = field_command(FieldPart::object, i, object_fields(), o, edited)) {
      commands.execute(*command);
    }
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip(visible ? "shown: click to hide" : "hidden");
  ImGui::SameLine();
  if (state.renaming == i) {
    if (state.focus_rename) {
      ImGui::SetKeyboardFocusHere();
      state.focus_rename = false;
    }
    ImGui::SetNextItemWidth(-1.0f);
    const bool enter =
        ImGui::InputText("##rename", &state.rename_text,
                         ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
    if (enter || ImGui::IsItemDeactivated()) {
      if (!ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)) &&
          state.rename_text != o.name) {
        commands.execute(RenameObject{i, state.rename_text});
      }
      state.renaming = -1;
    }
    ImGui::PopID();
    return;
  }
  const bool is_selected = std::binary_search(selected.begin(), selected.end(), i);
  const std::string material = o.material >= 0 && o.material < int(scene.material_names.size())
                                   ? scene.material_names[static_cast<std::size_t>(o.material)]
                                   : std::string("?");
  if (o.hidden)
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  if (ImGui::Selectable(o.name.empty() ? "(unnamed)" : o.name.c_str(), is_selected,
                        ImGuiSelectableFlags_AllowDoubleClick)) {
    if (ImGui::IsMouseDoubleClicked(0)) {
      state.renaming = i;
      state.rename_text = o.name;
      state.focus_rename = true;
    } else {
      click_row(selection, state, shown, static_cast<int>(scene.objects.size()), i);
    }
  }
  if (o.hidden) ImGui::PopStyleColor();
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("object %d, %s, material '%s'%s", i, to_string(o.type), material.c_str(),
                      o.hidden ? " (hidden)" : "");
  }
  if (ImGui::BeginPopupContextItem("##row")) {
    if (!is_selected) select_only(selection, i);
    selection_items(commands, selection, state, true);
    if (ImGui::BeginMenu("Assign material")) {
      for (std::size_t m = 0; m < scene.material_names.size(); ++m) {
        if (ImGui::MenuItem(scene.material_names[m].c_str(), nullptr, int(m) == o.material)) {
          commands.execute(AssignMaterial{selected_objects(selection, int(scene.objects.size())),
                                          static_cast<int>(m)});
        }
      }
      ImGui::EndMenu();
    }
    ImGui::EndPopup();
  }
  // The type and material, dim, at the right where the name leaves room (else the material
  // alone, else nothing: the tooltip has them).
  const float name_end = ImGui::GetItemRectMin().x + ImGui::GetStyle().FramePadding.x +
                         ImGui::CalcTextSize(o.name.c_str()).x + 12.0f;
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  for (const std::string& note : {std::string(to_string(o.type)) + "  " + material, material}) {
    const float width = ImGui::CalcTextSize(note.c_str()).x;
    if (name_end + width > right) continue;
    ImGui::SameLine(right - width - ImGui::GetWindowPos().x);
    ImGui::TextDisabled("%s", note.c_str());
    break;
  }
  ImGui::PopID();
}

// A transform field as a drag with a speed that suits it (the table gives key, label, help and
// range); a sphere's scale is one number.
bool transform_widget(const Field<ObjectTransform>& field, ObjectTransform& t, bool sphere) {
  const std::string key = field.key;
  const float speed = key == "rotate" ? 0.5f : 0.01f;
  FieldValue v = field.get(t);
  const FieldValue before = v;
  const float lo = static_cast<float>(field.min), hi = static_cast<float>(field.max);
  if (key == "scale" && sphere) {
    ImGui::DragFloat("scale", &v.v.x, speed, lo, hi, "%.3f");
    v.v = glm::vec3(v.v.x);
  } else {
    ImGui::DragFloat3(field.label, &v.v.x, speed, lo, hi, key == "rotate" ? "%.1f" : "%.3f");
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", field.help);
  if (v == before) return false;
  field.set(t, v);
  return true;
}

void draw_selected_object(Commands& commands, Selection& selection, OutlinerState& state) {
  const Scene& scene = commands.scene();
  const int count = static_cast<int>(scene.objects.size());
  if (count == 0) return;
  const int i = std::clamp(selection.object, 0, count - 1);
  const Object o = scene.objects[static_cast<std::size_t>(i)];  // a copy: commands replace it
  const std::vector<int> objects = selected_objects(selection, count);
  // The section's title with the reset button at its right, then the rule.
  ImGui::Spacing();
  ImGui::TextDisabled("%s", objects.size() > 1 ? "First of the selection" : "Selected object");
  ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - ImGui::CalcTextSize("Reset transform").x -
                  2 * ImGui::GetStyle().FramePadding.x);
  if (ImGui::SmallButton("Reset transform")) {
    std::vector<ObjectTransform> identities(objects.size());
    commands.execute(TransformObjects{objects, identities});
    return;
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "back to the object's own fields: no move, rotation or scale, the pivot at "
        "its centre");
  }
  ImGui::Separator();
  if (state.name_field_object != i) {
    state.name_field = o.name;
    state.name_field_object = i;
  }
  bool commit = ImGui::InputText("name", &state.name_field, ImGuiInputTextFlags_EnterReturnsTrue);
  commit = commit || ImGui::IsItemDeactivatedAfterEdit();
  if (commit && state.name_field != o.name) commands.execute(RenameObject{i, state.name_field});
  if (!ImGui::IsItemActive()) state.name_field = commands.scene().objects[std::size_t(i)].name;
  const std::string material = scene.material_names[static_cast<std::size_t>(o.material)];
  if (ImGui::BeginCombo("material", material.c_str())) {
    for (std::size_t m = 0; m < scene.material_names.size(); ++m) {
      if (ImGui::Selectable(scene.material_names[m].c_str(), int(m) == o.material)) {
        commands.execute(AssignMaterial{objects, static_cast<int>(m)});
      }
    }
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("give the selected objects an existing material");
  ObjectTransform t = o.transform;
  for (const Field<ObjectTransform>& field : transform_fields()) {
    transform_widget(field, t, o.type == ObjectType::sphere);
  }
  if (auto command = field_command(FieldPart::transform, i, transform_fields(), o.transform, t)) {
    commands.execute(*command);
  }
}

}  // namespace

void frame_selection(Commands& commands, const Selection& selection) {
  const Scene& scene = commands.scene();
  const std::vector<int> objects =
      selected_objects(selection, static_cast<int>(scene.objects.size()));
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (int i : objects) {
    glm::vec3 a, b;
    if (!object_bounds(scene.objects[static_cast<std::size_t>(i)], a, b)) continue;
    lo = glm::min(lo, a);
    hi = glm::max(hi, b);
  }
  if (!(lo.x <= hi.x)) return;
  const float aspect =
      static_cast<float>(scene.render.width) / static_cast<float>(std::max(scene.render.height, 1));
  commands.execute(SetCamera{frame_camera(scene.camera, lo, hi, aspect)});
}

void draw_outliner(Commands& commands, Selection& selection, OutlinerState& state,
                   FileBrowser& browser, ImVec2 pos, ImVec2 size) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
  if (!ImGui::Begin("Outliner", nullptr, flags)) {
    ImGui::End();
    return;
  }
  const Scene& scene = commands.scene();
  const int count = static_cast<int>(scene.objects.size());
  if (ImGui::SmallButton("Add...")) ImGui::OpenPopup("##add");
  if (ImGui::BeginPopup("##add")) {
    add_menu_items(commands, selection, browser);
    ImGui::EndPopup();
  }
  selection_items(commands, selection, state, false);
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::InputTextWithHint("##filter", "filter by name", &state.filter);

  std::vector<int> shown;
  for (int i = 0; i < count; ++i) {
    if (contains_ignoring_case(scene.objects[static_cast<std::size_t>(i)].name, state.filter)) {
      shown.push_back(i);
    }
  }
  const std::vector<int> selected = selected_objects(selection, count);
  // The list takes what the selected object's fields leave (about 8 rows), at least 4 rows.
  const float row = ImGui::GetFrameHeightWithSpacing();
  const float list_h = std::max(ImGui::GetContentRegionAvail().y - 8.2f * row, 4.0f * row);
  ImGui::BeginChild("##objects", ImVec2(0, list_h), true);
  ImGuiListClipper clipper;  // only the rows in view are drawn: 200 objects cost a screenful
  clipper.Begin(static_cast<int>(shown.size()));
  while (clipper.Step()) {
    for (int r = clipper.DisplayStart; r < clipper.DisplayEnd; ++r) {
      draw_row(commands, selection, state, shown, selected, shown[static_cast<std::size_t>(r)]);
      if (static_cast<int>(commands.scene().objects.size()) != count) break;  // deleted
    }
  }
  if (count == 0) ImGui::TextDisabled("no objects: Add... makes one");
  ImGui::EndChild();
  ImGui::TextDisabled("%d objects, %zu selected", count, selected.size());
  ImGui::PushItemWidth(-70.0f);
  if (static_cast<int>(commands.scene().objects.size()) == count) {
    draw_selected_object(commands, selection, state);
  }
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace gloss

// Materials with an identity (issue 24, item 2): the selected material's name and what can be
// done with it, the list of the scene's materials with their rendered balls, and the user's
// library beside the presets (material_parts.h).
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "editor/model/session/file_defaults.h"
#include "editor/ui/file_browser.h"
#include "editor/ui/panels/material_parts.h"
#include "editor/ui/panels/panel_state.h"
#include "editor/ui/panels/panel_widgets.h"
#include "editor/ui/parts/commands.h"
#include "editor/ui/parts/file_actions.h"
#include "editor/ui/parts/material_library.h"
#include "editor/ui/parts/selection.h"

namespace gloss {

namespace {

ImTextureID texture_id(GLuint texture) {
  return reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(texture));
}

// A swatch of side size at the cursor (a grey square until it is rendered), outlined when current.
void swatch_at(ImVec2 at, float size, GLuint texture, bool current) {
  ImDrawList* list = ImGui::GetWindowDrawList();
  if (texture != 0) {
    list->AddImage(texture_id(texture), at, ImVec2(at.x + size, at.y + size));
  } else {
    list->AddRectFilled(at, ImVec2(at.x + size, at.y + size), IM_COL32(60, 60, 66, 255));
  }
  if (current) {
    list->AddRect(ImVec2(at.x - 1, at.y - 1), ImVec2(at.x + size + 1, at.y + size + 1),
                  IM_COL32(242, 190, 50, 255), 0.0f, 0, 2.0f);
  }
}

int selected_material(const Scene& scene, const Selection& selection) {
  if (scene.objects.empty()) return -1;
  const int i = std::clamp(selection.object, 0, static_cast<int>(scene.objects.size()) - 1);
  return scene.objects[static_cast<std::size_t>(i)].material;
}

void try_action(Commands& commands, void (FileActions::*action)(), FileActions& files) {
  try {
    (files.*action)();
  } catch (const std::exception& e) {
    commands.error(e.what());
  }
}

}  // namespace

void draw_material_identity(Commands& commands, const Selection& selection,
                            MaterialPanelState& state, FileActions& files, FileBrowser& browser) {
  const Scene& scene = commands.scene();
  const int m = selected_material(scene, selection);
  if (m < 0 || m >= static_cast<int>(scene.material_names.size())) return;
  const std::string name = scene.material_names[static_cast<std::size_t>(m)];
  if (state.name_field_material != m) {
    state.name_field = name;
    state.name_field_material = m;
  }
  ImGui::SetNextItemWidth(-1.0f);
  bool commit =
      ImGui::InputText("##material-name", &state.name_field, ImGuiInputTextFlags_EnterReturnsTrue);
  commit = commit || ImGui::IsItemDeactivatedAfterEdit();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the material's name: type to rename it");
  if (commit && state.name_field != name) {
    commands.execute(RenameMaterial{name, state.name_field});
  }
  if (!ImGui::IsItemActive()) {
    state.name_field = commands.scene().material_names[static_cast<std::size_t>(m)];
  }
  const std::vector<int> objects =
      selected_objects(selection, static_cast<int>(scene.objects.size()));
  const long users = std::count_if(scene.objects.begin(), scene.objects.end(),
                                   [&](const Object& o) { return o.material == m; });
  if (ImGui::SmallButton("Copy")) {
    commands.execute(NewMaterial{objects, scene.materials[static_cast<std::size_t>(m)], name});
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("a copy of '%s' for the selected objects, to edit apart", name.c_str());
  }
  ImGui::SameLine();
  if (ImGui::SmallButton("Save...")) {
    browser.start(BrowsePurpose::save_material, scene.path, file_name_for(name, ".json"));
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("save '%s' alone to a file", name.c_str());
  ImGui::SameLine();
  if (ImGui::SmallButton("To library")) try_action(commands, &FileActions::save_to_library, files);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("save '%s' into your library folder; it shows beside the presets",
                      name.c_str());
  }
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped(
      "%s", users > 1 ? "shared: edits change every object using it" : "used by this object alone");
  ImGui::PopStyleColor();
}

void draw_material_list(Commands& commands, Selection& selection, MaterialPanelState& state,
                        MaterialLibrary& library) {
  const Scene& scene = commands.scene();
  const int count = static_cast<int>(scene.objects.size());
  const int current = selected_material(scene, selection);
  const std::vector<int> objects = selected_objects(selection, count);
  const float icon = ImGui::GetTextLineHeight() + 6.0f;
  for (std::size_t m = 0; m < scene.materials.size(); ++m) {
    // Copies: a command below replaces the scene's vectors.
    const std::string name = scene.material_names[m];
    const Material material = scene.materials[m];
    const long users = std::count_if(scene.objects.begin(), scene.objects.end(),
                                     [&](const Object& o) { return o.material == int(m); });
    ImGui::PushID(static_cast<int>(m));
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const GLuint texture = library.balls.texture("scene:" + name, material);
    if (state.renaming == static_cast<int>(m)) {
      ImGui::Dummy(ImVec2(icon, icon));
      ImGui::SameLine();
      if (state.focus_rename) {
        ImGui::SetKeyboardFocusHere();
        state.focus_rename = false;
      }
      ImGui::SetNextItemWidth(-1.0f);
      const bool enter = ImGui::InputText(
          "##rename", &state.rename_text,
          ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
      if (enter || ImGui::IsItemDeactivated()) {
        if (state.rename_text != name) commands.execute(RenameMaterial{name, state.rename_text});
        state.renaming = -1;
      }
    } else {
      const bool clicked =
          ImGui::Selectable("##material", int(m) == current, ImGuiSelectableFlags_AllowDoubleClick,
                            ImVec2(0.0f, icon));
      if (clicked && ImGui::IsMouseDoubleClicked(0)) {
        state.renaming = static_cast<int>(m);
        state.rename_text = name;
        state.focus_rename = true;
      } else if (clicked && !objects.empty()) {
        commands.execute(AssignMaterial{objects, static_cast<int>(m)});
      }
      if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(
            "click: give the selected objects '%s'; double-click: rename; "
            "right-click: more",
            name.c_str());
      }
      if (ImGui::BeginPopupContextItem("##material-menu")) {
        if (ImGui::MenuItem("Assign to the selection")) {
          commands.execute(AssignMaterial{objects, static_cast<int>(m)});
        }
        if (ImGui::MenuItem("Select the objects using it", nullptr, false, users > 0)) {
          std::vector<int> using_it;
          for (int i = 0; i < count; ++i) {
            if (scene.objects[static_cast<std::size_t>(i)].material == int(m))
              using_it.push_back(i);
          }
          select_all_of(selection, using_it);
        }
        if (ImGui::MenuItem("Rename")) {
          state.renaming = static_cast<int>(m);
          state.rename_text = name;
          state.focus_rename = true;
        }
        if (ImGui::MenuItem("Copy for the selection")) {
          commands.execute(NewMaterial{objects, material, name});
        }
        ImGui::EndPopup();
      }
      const std::string text =
          name + (users == 1 ? "  (1 object)" : "  (" + std::to_string(users) + " objects)");
      ImGui::GetWindowDrawList()->AddText(
          ImVec2(at.x + icon + 6.0f, at.y + 3.0f),
          ImGui::GetColorU32(users > 0 ? ImGuiCol_Text : ImGuiCol_TextDisabled), text.c_str());
    }
    swatch_at(at, icon, texture, false);
    ImGui::PopID();
  }
}

void draw_user_library(Commands& commands, const Selection& selection, MaterialLibrary& library,
                       FileActions& files) {
  const Scene& scene = commands.scene();
  if (ImGui::SmallButton("Reload")) try_action(commands, &FileActions::reload_library, files);
  ImGui::SameLine();
  ImGui::TextDisabled("%s", library.folder.string().c_str());
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("your library folder: materials files (.json, .mtl) there show here");
  }
  if (library.user.empty()) {
    ImGui::TextDisabled("empty: \"To library\" above saves the selected material here");
    return;
  }
  if (scene.objects.empty()) return;
  const int object = std::clamp(selection.object, 0, static_cast<int>(scene.objects.size()) - 1);
  const std::vector<int> objects =
      selected_objects(selection, static_cast<int>(scene.objects.size()));
  const float icon = ImGui::GetTextLineHeight() + 4.0f;
  const int columns = std::clamp(static_cast<int>(ImGui::GetContentRegionAvail().x / 118.0f), 1, 4);
  if (!ImGui::BeginTable("##library", columns, ImGuiTableFlags_SizingStretchSame)) return;
  for (std::size_t i = 0; i < library.user.size(); ++i) {
    const LibraryMaterial entry = library.user[i];  // a copy: Reload replaces the list
    ImGui::TableNextColumn();
    ImGui::PushID(static_cast<int>(i));
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const bool clicked = ImGui::Selectable("##entry", false, 0, ImVec2(0.0f, icon));
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("%s (%s): click to load into the selected material; right-click: more",
                        entry.name.c_str(), entry.file.c_str());
    }
    if (clicked) commands.execute(SetMaterial{object, entry.material, entry.name});
    if (ImGui::BeginPopupContextItem("##entry-menu")) {
      if (ImGui::MenuItem("Add as a new material for the selection")) {
        commands.execute(NewMaterial{objects, entry.material, entry.name});
      }
      ImGui::EndPopup();
    }
    swatch_at(at, icon,
              library.balls.texture("library:" + entry.file + ":" + entry.name, entry.material),
              false);
    ImGui::GetWindowDrawList()->AddText(ImVec2(at.x + icon + 4.0f, at.y + 2.0f),
                                        ImGui::GetColorU32(ImGuiCol_Text), entry.name.c_str());
    ImGui::PopID();
  }
  ImGui::EndTable();
}

}  // namespace gloss

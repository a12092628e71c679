// The Material panel: the selected object's material constants, the preset swatches, the shading
// model switch. Widgets edit a copy; one place at the end turns a change into a command.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>

#include <imgui.h>

#include "editor/model/document/preset_status.h"
#include "editor/ui/file_browser.h"
#include "editor/ui/panels/field_widgets.h"
#include "editor/ui/panels/map_slots.h"
#include "editor/ui/panels/material_parts.h"
#include "editor/ui/panels/panel_state.h"
#include "editor/ui/panels/panel_widgets.h"
#include "editor/ui/panels/panels.h"
#include "editor/ui/parts/commands.h"
#include "editor/ui/parts/material_library.h"
#include "editor/ui/parts/selection.h"
#include "io/material/preset_table.h"

namespace gloss {

namespace {

// The preset swatches with their names: a table of small swatches, each with its name beside
// it ("black plastic"), clipped to the column; the current preset is outlined, and a tweaked one
// is named "(modified)" in the heading above.
void draw_presets(Commands& commands, const Swatches& swatches, int object,
                  const Material& material) {
  const std::vector<Preset>& presets = preset_table();
  const float icon = ImGui::GetTextLineHeight() + 4.0f;
  const int columns = std::clamp(static_cast<int>(ImGui::GetContentRegionAvail().x / 118.0f), 1, 4);
  if (!ImGui::BeginTable("##presets", columns, ImGuiTableFlags_SizingStretchSame)) return;
  for (std::size_t i = 0; i < presets.size(); ++i) {
    ImGui::TableNextColumn();
    ImGui::PushID(static_cast<int>(i));
    const bool current = presets[i].name == material.preset;
    std::string name = presets[i].name;
    std::replace(name.begin(), name.end(), '_', ' ');
    const ImVec2 at = ImGui::GetCursorScreenPos();
    // One selectable row per preset: swatch and name click alike.
    const bool clicked = ImGui::Selectable("##preset", current, 0, ImVec2(0.0f, icon));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", presets[i].name.c_str());
    ImDrawList* list = ImGui::GetWindowDrawList();
    if (GLuint texture = swatches.texture(i); texture != 0) {
      list->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(texture)), at,
                     ImVec2(at.x + icon, at.y + icon));
    } else {
      list->AddRectFilled(at, ImVec2(at.x + icon, at.y + icon), IM_COL32(60, 60, 66, 255));
    }
    if (current) {
      list->AddRect(ImVec2(at.x - 1, at.y - 1), ImVec2(at.x + icon + 1, at.y + icon + 1),
                    IM_COL32(242, 190, 50, 255), 0.0f, 0, 2.0f);
    }
    list->AddText(ImVec2(at.x + icon + 4.0f, at.y + 2.0f), ImGui::GetColorU32(ImGuiCol_Text),
                  name.c_str());
    if (clicked) commands.execute(ApplyPreset{object, presets[i].name});
    ImGui::PopID();
  }
  ImGui::EndTable();
}

void draw_model_switch(Commands& commands, ViewSettings& view) {
  const RenderSettings& render = commands.scene().render;
  section_title("Shading model (whole scene)");
  int model = render.model == ShadingModel::phong ? 0 : 1;
  bool changed = ImGui::RadioButton("Phong (R.V)", &model, 0);
  same_line_if_fits(toggle_width("Blinn-Phong (N.H)"));
  changed |= ImGui::RadioButton("Blinn-Phong (N.H)", &model, 1);
  if (changed) {
    commands.execute(SetModel{model == 0 ? ShadingModel::phong : ShadingModel::blinn_phong,
                              view.keep_highlight_size});
  }
  // One setting for both uses (view_settings.h): the switch above and the A/B view's B side.
  ImGui::Checkbox("keep highlight size (x4 rule)", &view.keep_highlight_size);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Blinn-Phong exponent = 4 x Phong exponent: near the peak the half vector\n"
        "turns half as far as the reflection vector, so the lobes match.\n"
        "Used when the model is switched here, and by the A/B view (B side).");
  }
  RenderSettings edited = render;
  field_widget(*find_field(render_fields(), "energy_normalize"), edited);
  if (auto command = field_command(FieldPart::render, 0, render_fields(), render, edited)) {
    commands.execute(*command);
  }
}

void draw_library(Commands& commands, const MaterialLibrary& library, int object) {
  const std::vector<NamedMaterial>& loaded = library.loaded;
  if (loaded.empty()) return;
  section_title(("Loaded from " + library.loaded_from).c_str());
  for (std::size_t i = 0; i < loaded.size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    if (ImGui::Button("Apply")) {
      commands.execute(SetMaterial{object, loaded[i].second, loaded[i].first});
    }
    ImGui::SameLine();
    ImGui::TextUnformatted(loaded[i].first.c_str());
    ImGui::PopID();
  }
}

}  // namespace

void draw_material_panel(Commands& commands, Selection& selection, ViewSettings& view,
                         MaterialPanelState& state, MaterialLibrary& library, FileActions& files,
                         FileBrowser& browser, ImVec2 pos, ImVec2 size) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
  if (!ImGui::Begin("Material", nullptr, flags)) {
    ImGui::End();
    return;
  }
  const Scene& scene = commands.scene();
  if (scene.objects.empty()) {
    ImGui::TextWrapped("The scene has no objects. Open a scene or add a model (File menu).");
    draw_model_switch(commands, view);
    ImGui::End();
    return;
  }
  selection.object = std::clamp(selection.object, 0, static_cast<int>(scene.objects.size()) - 1);
  const int object = selection.object;
  ImGui::TextDisabled("of %s", object_label(scene, object).c_str());
  const int material_index = scene.objects[object].material;
  // A copy: an executed command replaces the scene's vectors, and this is read afterwards.
  const Material material = scene.materials[material_index];
  draw_material_identity(commands, selection, state, files, browser);

  Material edited = material;
  ImGui::PushItemWidth(-label_room(120.0f));  // room for the longest label, "Phong exponent"
  ImGui::Checkbox("link RGB channels", &state.link_channels);
  // The exponent's label names the model it is the exponent of.
  const bool blinn = scene.render.model == ShadingModel::blinn_phong;
  // In a narrow panel the exponent's label is its symbol (the tooltip names the model).
  const bool short_label = ImGui::CalcTextSize("Phong exponent").x > label_room(120.0f);
  const char* exponent_label = short_label ? "alpha##shininess"
                               : blinn     ? "Blinn exponent##shininess"
                                           : "Phong exponent##shininess";
  for (const Field<Material>& field : material_fields()) {
    // Maps have their rows below (map_slots.h); a map's scale shows once there is that map.
    if (field.kind == FieldKind::map || !field.applies_to(edited)) continue;
    const bool exponent = std::string(field.key) == "shininess";
    field_widget(field, edited, state.link_channels, exponent ? exponent_label : nullptr);
    if (exponent && ImGui::IsItemHovered()) {
      ImGui::SetTooltip("%s", blinn ? "alpha of (N.H)^alpha, Blinn-Phong; drag: 1% per pixel, "
                                      "Shift faster, Alt finer, Ctrl+click to type"
                                    : "alpha of (R.V)^alpha, Phong; drag: 1% per pixel, "
                                      "Shift faster, Alt finer, Ctrl+click to type");
    }
  }
  ImGui::PopItemWidth();
  if (auto command =
          field_command(FieldPart::material, object, material_fields(), material, edited)) {
    commands.execute(*command);
  }
  draw_map_slots(commands, browser, state.thumbnails, object, material,
                 scene_folder(scene.path, view.screenshot_dir).string());

  section_title("Presets");
  if (!material.preset.empty()) {
    ImGui::Text("preset: %s", preset_status(material).c_str());
    if (preset_modified(material)) {
      ImGui::SameLine();
      if (ImGui::SmallButton("Reset")) commands.execute(ApplyPreset{object, material.preset});
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("reload '%s', undoing the tweaks", material.preset.c_str());
    }
  } else {
    ImGui::TextDisabled("custom material (no preset)");
  }
  const Swatches& swatches = library.swatches;
  if (!swatches.error().empty()) {
    ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "swatches: %s", swatches.error().c_str());
  }
  draw_presets(commands, swatches, object, material);
  section_title("Your library");
  draw_user_library(commands, selection, library, files);
  section_title("Scene materials (click: give to the selection)");
  draw_material_list(commands, selection, state, library);
  draw_model_switch(commands, view);
  draw_library(commands, library, object);
  ImGui::End();
}

}  // namespace gloss

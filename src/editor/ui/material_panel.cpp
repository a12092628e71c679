// The Material panel: the selected object's material constants, the preset swatches, the shading
// model switch. Widgets edit a copy; one place at the end turns a change into a command.
#include <algorithm>
#include <cstdint>
#include <optional>

#include <imgui.h>

#include "editor/ui/app.h"
#include "editor/ui/field_widgets.h"
#include "editor/ui/panel_widgets.h"
#include "io/preset_table.h"

namespace gloss {

namespace {

void draw_presets(App& app, int object, const Material& material) {
  const std::vector<Preset>& presets = preset_table();
  const float cell = static_cast<float>(Swatches::kSize) * 0.8f;
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const int per_row =
      std::max(1, static_cast<int>((ImGui::GetContentRegionAvail().x + spacing) /
                                   (cell + 2.0f * ImGui::GetStyle().FramePadding.x + spacing)));
  for (std::size_t i = 0; i < presets.size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    const bool current = presets[i].name == material.preset;
    if (current) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.95f, 0.75f, 0.2f, 1.0f));
    bool clicked = false;
    if (GLuint texture = app.swatches.texture(i); texture != 0) {
      clicked = ImGui::ImageButton(
          reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(texture)), ImVec2(cell, cell));
    } else {
      clicked = ImGui::Button("...", ImVec2(cell + 2.0f * ImGui::GetStyle().FramePadding.x,
                                            cell + 2.0f * ImGui::GetStyle().FramePadding.y));
    }
    if (current) ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", presets[i].name.c_str());
    if (clicked) execute(app, ApplyPreset{object, presets[i].name});
    if ((i + 1) % per_row != 0 && i + 1 < presets.size()) ImGui::SameLine();
    ImGui::PopID();
  }
}

void draw_model_switch(App& app) {
  const RenderSettings& render = app.commands.scene().render;
  section_title("Shading model (whole scene)");
  int model = render.model == ShadingModel::phong ? 0 : 1;
  bool changed = ImGui::RadioButton("Phong (R.V)", &model, 0);
  ImGui::SameLine();
  changed |= ImGui::RadioButton("Blinn-Phong (N.H)", &model, 1);
  if (changed) {
    execute(app, SetModel{model == 0 ? ShadingModel::phong : ShadingModel::blinn_phong,
                          app.view.keep_highlight_size});
  }
  ImGui::Checkbox("keep highlight size on switch", &app.view.keep_highlight_size);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Blinn-Phong exponent = 4 x Phong exponent: near the peak the half vector\n"
        "turns half as far as the reflection vector, so the lobes match.");
  }
  RenderSettings edited = render;
  field_widget(*find_field(render_fields(), "energy_normalize"), edited);
  if (auto command = field_command(FieldPart::render, 0, render_fields(), render, edited)) {
    execute(app, *command);
  }
}

void draw_library(App& app, int object) {
  if (app.library.empty()) return;
  section_title(("Loaded from " + app.library_source).c_str());
  for (std::size_t i = 0; i < app.library.size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    if (ImGui::Button("Apply")) {
      execute(app, SetMaterial{object, app.library[i].second, app.library[i].first});
    }
    ImGui::SameLine();
    ImGui::TextUnformatted(app.library[i].first.c_str());
    ImGui::PopID();
  }
}

}  // namespace

void draw_material_panel(App& app, ImVec2 pos, ImVec2 size) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
  if (!ImGui::Begin("Material", nullptr, flags)) {
    ImGui::End();
    return;
  }
  const Scene& scene = app.commands.scene();
  if (scene.objects.empty()) {
    ImGui::TextWrapped("The scene has no objects. Open a scene or add a model (File menu).");
    draw_model_switch(app);
    ImGui::End();
    return;
  }
  app.selected_object =
      std::clamp(app.selected_object, 0, static_cast<int>(scene.objects.size()) - 1);
  const int object = app.selected_object;
  const std::string current = object_label(scene, object);
  if (ImGui::BeginCombo("object", current.c_str())) {
    for (int i = 0; i < static_cast<int>(scene.objects.size()); ++i) {
      if (ImGui::Selectable(object_label(scene, i).c_str(), i == object)) app.selected_object = i;
    }
    ImGui::EndCombo();
  }
  const int material_index = scene.objects[object].material;
  // A copy: an executed command replaces the scene's vectors, and this is read afterwards.
  const Material material = scene.materials[material_index];
  const long users = std::count_if(scene.objects.begin(), scene.objects.end(),
                                   [&](const Object& o) { return o.material == material_index; });
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("material '%s'%s", scene.material_names[material_index].c_str(),
                     users > 1 ? " (shared: edits change every object using it)" : "");
  ImGui::PopStyleColor();

  Material edited = material;
  ImGui::Checkbox("link RGB channels", &app.link_channels);
  for (const Field<Material>& field : material_fields()) {
    field_widget(field, edited, app.link_channels);
  }
  if (auto command =
          field_command(FieldPart::material, object, material_fields(), material, edited)) {
    execute(app, *command);
  }

  section_title("Presets");
  if (!material.preset.empty()) {
    const std::string reset = "Reset to preset '" + material.preset + "'";
    if (ImGui::Button(reset.c_str())) execute(app, ApplyPreset{object, material.preset});
  } else {
    ImGui::TextDisabled("custom material (no preset)");
  }
  if (!app.swatches.error().empty()) {
    ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "swatches: %s", app.swatches.error().c_str());
  }
  draw_presets(app, object, material);
  draw_model_switch(app);
  draw_library(app, object);
  ImGui::End();
}

}  // namespace gloss

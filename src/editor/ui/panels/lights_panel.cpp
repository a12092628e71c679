// The Lights & Scene panel: lights of every type (add, add a headlight, remove, the fields the
// type uses, the orbit-light animation), the environment light (a shipped map or a file,
// intensity, rotation, background), the scene's ambient, background and shadows, opening files.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>

#include <imgui.h>

#include "editor/model/view/camera_controller.h"
#include "editor/ui/file_browser.h"
#include "editor/ui/panels/field_widgets.h"
#include "editor/ui/panels/panel_widgets.h"
#include "editor/ui/panels/panels.h"
#include "editor/ui/parts/commands.h"
#include "editor/ui/parts/selection.h"

namespace gloss {

namespace {

void draw_lights(Commands& commands, Selection& selection, ViewSettings& view) {
  const Scene& scene = commands.scene();
  const int count = static_cast<int>(scene.lights.size());
  if (ImGui::Button("Add light")) {
    PointLight light;
    // In view (upper right of the image), so its marker shows and it can be dragged at once.
    const RenderSettings& r = scene.render;
    light.position = new_light_position(scene.camera, r.width, r.height);
    if (commands.execute(AddLight{light})) {
      // Selected at once; the rest of the panel waits for the next frame, whose count includes
      // it (clamping against this frame's count unselected it).
      selection.light = count;
      return;
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Add headlight")) {
    // A directional light that follows the camera, straight ahead: VRML's headlight.
    Light light;
    light.type = LightType::directional;
    light.direction = glm::vec3(0.0f, 0.0f, -1.0f);
    light.follow_camera = true;
    if (commands.execute(AddLight{light})) {
      selection.light = count;
      return;
    }
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("a directional light from the eye that turns with the camera");
  }
  if (count == 0) {
    disabled_text_wrapped("no lights: only ambient, emission and the environment show");
    return;
  }
  selection.light = std::clamp(selection.light, 0, count - 1);
  ImGui::SameLine();
  if (ImGui::Button("Remove")) {
    commands.execute(RemoveLight{selection.light});
    return;
  }
  ImGui::BeginChild("##light-list",
                    ImVec2(0, ImGui::GetTextLineHeightWithSpacing() * std::min(count, 4) + 8.0f),
                    true);
  for (int i = 0; i < count; ++i) {
    const Light& l = scene.lights[i];
    const glm::vec3& p = l.type == LightType::directional ? l.direction : l.position;
    char label[112];
    std::snprintf(label, sizeof label, "%s %d %s (%.2f, %.2f, %.2f)%s", to_string(l.type), i,
                  l.type == LightType::directional ? "towards" : "at", p.x, p.y, p.z,
                  l.type == LightType::directional && l.follow_camera ? " headlight" : "");
    if (ImGui::Selectable(label, i == selection.light)) selection.light = i;
  }
  ImGui::EndChild();

  const PointLight light = scene.lights[selection.light];  // a copy: commands replace the vector
  PointLight edited = light;
  // The fields the light's type uses (the others are kept, not shown).
  for (const Field<PointLight>& field : light_fields()) {
    if (field.applies_to(light)) field_widget(field, edited);
  }
  if (auto command =
          field_command(FieldPart::light, selection.light, light_fields(), light, edited)) {
    commands.execute(*command);
  }
  if (light.type != LightType::point) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("%s",
                       light.type == LightType::spot
                           ? "viewport: drag the marker to move it, the cone's handle to aim it"
                           : "viewport: drag the arrow's handle to turn it");
    ImGui::PopStyleColor();
  }
  ImGui::Checkbox("orbit light", &view.orbit_light);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::SliderFloat("##orbit-speed", &view.orbit_speed, -180.0f, 180.0f, "%.0f deg/s");
}

void draw_scene(Commands& commands, FileBrowser& browser) {
  const Scene& scene = commands.scene();
  Scene edited = scene;
  for (const Field<Scene>& field : scene_fields()) field_widget(field, edited);
  field_widget(*find_field(render_fields(), "shadows"), edited.render);
  if (auto command = field_command(FieldPart::scene, 0, scene_fields(), scene, edited)) {
    commands.execute(*command);
  } else if (auto render = field_command(FieldPart::render, 0, render_fields(), scene.render,
                                         edited.render)) {
    commands.execute(*render);
  }
  ImGui::TextDisabled("%zu objects, %zu materials: the Outliner lists them", scene.objects.size(),
                      scene.materials.size());
  if (ImGui::Button("Open scene...")) browser.start(BrowsePurpose::open_scene, scene.path, "");
  ImGui::SameLine();
  if (ImGui::Button("Add model...")) browser.start(BrowsePurpose::add_model, scene.path, "");
}

// The environment light: a shipped map or a file, none; its table's fields (intensity,
// rotation, background). Ctrl+drag in the viewport turns it too.
void draw_environment(Commands& commands, const ViewSettings& view, FileBrowser& browser) {
  const Scene& scene = commands.scene();
  const Environment& environment = scene.environment;
  const std::string shown = environment.present()
                                ? std::filesystem::path(environment.file).filename().string()
                                : std::string("none");
  if (ImGui::BeginCombo("map", shown.c_str())) {
    if (ImGui::Selectable("none", !environment.present())) commands.execute(SetEnvironment{});
    for (const std::string& name : shipped_environments()) {
      const bool current =
          environment.present() && std::filesystem::path(environment.file).stem().string() == name;
      if (ImGui::Selectable((name + " (shipped)").c_str(), current)) {
        commands.execute(SetEnvironment{name});
      }
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::Button("File...")) {
    browser.show(BrowsePurpose::open_environment, scene_folder(scene.path, view.screenshot_dir),
                 "");
  }
  if (!environment.present()) {
    ImGui::TextDisabled("no environment: HDR, EXR or PNG, equirectangular");
    return;
  }
  Environment edited = environment;
  for (const Field<Environment>& field : environment_fields()) field_widget(field, edited);
  if (auto command =
          field_command(FieldPart::environment, 0, environment_fields(), environment, edited)) {
    commands.execute(*command);
  }
  ImGui::TextDisabled("%d x %d; Ctrl+drag the image to turn it", environment.map->radiance.width,
                      environment.map->radiance.height);
}

}  // namespace

void draw_lights_panel(Commands& commands, Selection& selection, ViewSettings& view,
                       FileBrowser& browser, ImVec2 pos, ImVec2 size) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
  if (!ImGui::Begin("Lights & Scene", nullptr, flags)) {
    ImGui::End();
    return;
  }
  ImGui::PushItemWidth(-label_room(110.0f));
  section_title("Lights");
  draw_lights(commands, selection, view);
  section_title("Environment");
  draw_environment(commands, view, browser);
  section_title("Scene");
  draw_scene(commands, browser);
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace gloss

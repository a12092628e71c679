// The Lights & Scene panel: point lights (add, remove, position, colours, attenuation, the
// orbit-light animation), the scene's ambient, background and shadows, and opening files.
#include <algorithm>
#include <cstdio>
#include <optional>

#include <imgui.h>

#include "editor/ui/app.h"
#include "editor/ui/panel_widgets.h"

namespace gloss {

namespace {

constexpr ImGuiColorEditFlags kColourFlags =
    ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR | ImGuiColorEditFlags_DisplayRGB;

// The one command for an edited copy of a light: the first value that differs.
std::optional<Command> light_command(int index, const PointLight& before, const PointLight& after) {
  for (LightField f : {LightField::position, LightField::ambient, LightField::diffuse,
                       LightField::specular, LightField::attenuation}) {
    if (light_value(after, f) != light_value(before, f)) {
      return SetLightValue{index, f, light_value(after, f)};
    }
  }
  return std::nullopt;
}

void draw_lights(App& app) {
  const Scene& scene = app.commands.scene();
  const int count = static_cast<int>(scene.lights.size());
  if (ImGui::Button("Add light")) {
    PointLight light;
    light.position = scene.camera.eye + glm::vec3(0.0f, 2.0f, 0.0f);
    if (execute(app, AddLight{light})) app.selected_light = count;
  }
  if (count == 0) {
    ImGui::SameLine();
    ImGui::TextDisabled("no lights: only ambient and emission show");
    return;
  }
  app.selected_light = std::clamp(app.selected_light, 0, count - 1);
  ImGui::SameLine();
  if (ImGui::Button("Remove")) {
    execute(app, RemoveLight{app.selected_light});
    return;
  }
  ImGui::BeginChild("##light-list",
                    ImVec2(0, ImGui::GetTextLineHeightWithSpacing() * std::min(count, 4) + 8.0f),
                    true);
  for (int i = 0; i < count; ++i) {
    const glm::vec3& p = scene.lights[i].position;
    char label[96];
    std::snprintf(label, sizeof label, "light %d at (%.2f, %.2f, %.2f)", i, p.x, p.y, p.z);
    if (ImGui::Selectable(label, i == app.selected_light)) app.selected_light = i;
  }
  ImGui::EndChild();

  const PointLight light = scene.lights[app.selected_light];  // a copy: commands replace the vector
  PointLight edited = light;
  bool changed = false;
  changed |= ImGui::DragFloat3("position", &edited.position.x, 0.02f, -1e4f, 1e4f, "%.2f");
  changed |= ImGui::ColorEdit3("La ambient", &edited.ambient.x, kColourFlags);
  changed |= ImGui::ColorEdit3("Ld diffuse", &edited.diffuse.x, kColourFlags);
  changed |= ImGui::ColorEdit3("Ls specular", &edited.specular.x, kColourFlags);
  changed |= ImGui::DragFloat3("attenuation", &edited.attenuation.x, 0.005f, 0.0f, 100.0f, "%.3f");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("c0, c1, c2: 1 / (c0 + c1 d + c2 d^2)");
  if (changed) {
    edited.ambient = glm::max(edited.ambient, glm::vec3(0.0f));
    edited.diffuse = glm::max(edited.diffuse, glm::vec3(0.0f));
    edited.specular = glm::max(edited.specular, glm::vec3(0.0f));
    edited.attenuation = glm::max(edited.attenuation, glm::vec3(0.0f));
    if (std::optional<Command> command = light_command(app.selected_light, light, edited)) {
      execute(app, *command);
    }
  }
  ImGui::Checkbox("orbit light", &app.view.orbit_light);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::SliderFloat("##orbit-speed", &app.view.orbit_speed, -180.0f, 180.0f, "%.0f deg/s");
}

void draw_scene(App& app) {
  const Scene& scene = app.commands.scene();
  glm::vec3 ambient = scene.ambient, background = scene.background;
  if (ImGui::ColorEdit3("scene ambient", &ambient.x, kColourFlags)) {
    execute(app, SetSceneAmbient{glm::max(ambient, glm::vec3(0.0f))});
  }
  if (ImGui::ColorEdit3("background", &background.x, kColourFlags)) {
    execute(app, SetBackground{glm::max(background, glm::vec3(0.0f))});
  }
  bool shadows = scene.render.shadows;
  if (ImGui::Checkbox("shadows", &shadows)) execute(app, SetShadows{shadows});
  ImGui::TextDisabled("%zu objects, %zu materials; click an object in the viewport to select it",
                      scene.objects.size(), scene.materials.size());
  const std::filesystem::path folder = scene.path.empty()
                                           ? std::filesystem::path(app.view.screenshot_dir)
                                           : std::filesystem::path(scene.path).parent_path();
  if (ImGui::Button("Open scene...")) app.browser.show(BrowsePurpose::open_scene, folder, "");
  ImGui::SameLine();
  if (ImGui::Button("Add OBJ...")) app.browser.show(BrowsePurpose::add_obj, folder, "");
}

}  // namespace

void draw_lights_panel(App& app, ImVec2 pos, ImVec2 size) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
  if (!ImGui::Begin("Lights & Scene", nullptr, flags)) {
    ImGui::End();
    return;
  }
  ImGui::PushItemWidth(-110.0f);
  section_title("Point lights");
  draw_lights(app);
  section_title("Scene");
  draw_scene(app);
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace gloss

// The Lights & Scene panel: point lights (add, remove, position, colours, attenuation, the
// orbit-light animation), the scene's ambient, background and shadows, and opening files.
#include <algorithm>
#include <cstdio>
#include <optional>

#include <imgui.h>

#include "editor/model/view/camera_controller.h"
#include "editor/ui/app.h"
#include "editor/ui/panels/field_widgets.h"
#include "editor/ui/panels/panel_widgets.h"

namespace gloss {

namespace {

void draw_lights(App& app) {
  const Scene& scene = app.commands.scene();
  const int count = static_cast<int>(scene.lights.size());
  if (ImGui::Button("Add light")) {
    PointLight light;
    // In view (upper right of the image), so its marker shows and it can be dragged at once.
    const RenderSettings& r = scene.render;
    light.position = new_light_position(scene.camera, r.width, r.height);
    if (execute(app, AddLight{light})) {
      // Selected at once; the rest of the panel waits for the next frame, whose count includes
      // it (clamping against this frame's count unselected it).
      app.selected_light = count;
      return;
    }
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
  for (const Field<PointLight>& field : light_fields()) field_widget(field, edited);
  if (auto command =
          field_command(FieldPart::light, app.selected_light, light_fields(), light, edited)) {
    execute(app, *command);
  }
  ImGui::Checkbox("orbit light", &app.view.orbit_light);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::SliderFloat("##orbit-speed", &app.view.orbit_speed, -180.0f, 180.0f, "%.0f deg/s");
}

void draw_scene(App& app) {
  const Scene& scene = app.commands.scene();
  Scene edited = scene;
  for (const Field<Scene>& field : scene_fields()) field_widget(field, edited);
  field_widget(*find_field(render_fields(), "shadows"), edited.render);
  if (auto command = field_command(FieldPart::scene, 0, scene_fields(), scene, edited)) {
    execute(app, *command);
  } else if (auto render = field_command(FieldPart::render, 0, render_fields(), scene.render,
                                         edited.render)) {
    execute(app, *render);
  }
  ImGui::TextDisabled("%zu objects, %zu materials; click an object in the viewport to select it",
                      scene.objects.size(), scene.materials.size());
  const std::filesystem::path folder = scene.path.empty()
                                           ? std::filesystem::path(app.view.screenshot_dir)
                                           : std::filesystem::path(scene.path).parent_path();
  if (ImGui::Button("Open scene...")) app.browser.show(BrowsePurpose::open_scene, folder, "");
  ImGui::SameLine();
  if (ImGui::Button("Add model...")) app.browser.show(BrowsePurpose::add_model, folder, "");
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

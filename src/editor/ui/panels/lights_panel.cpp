// The Lights & Scene panel: point lights (add, remove, position, colours, attenuation, the
// orbit-light animation), the scene's ambient, background and shadows, and opening files.
#include <algorithm>
#include <cstdio>
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
  if (count == 0) {
    ImGui::SameLine();
    ImGui::TextDisabled("no lights: only ambient and emission show");
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
    const glm::vec3& p = scene.lights[i].position;
    char label[96];
    std::snprintf(label, sizeof label, "light %d at (%.2f, %.2f, %.2f)", i, p.x, p.y, p.z);
    if (ImGui::Selectable(label, i == selection.light)) selection.light = i;
  }
  ImGui::EndChild();

  const PointLight light = scene.lights[selection.light];  // a copy: commands replace the vector
  PointLight edited = light;
  for (const Field<PointLight>& field : light_fields()) field_widget(field, edited);
  if (auto command =
          field_command(FieldPart::light, selection.light, light_fields(), light, edited)) {
    commands.execute(*command);
  }
  ImGui::Checkbox("orbit light", &view.orbit_light);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::SliderFloat("##orbit-speed", &view.orbit_speed, -180.0f, 180.0f, "%.0f deg/s");
}

void draw_scene(Commands& commands, const ViewSettings& view, FileBrowser& browser) {
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
  ImGui::TextDisabled("%zu objects, %zu materials; click an object in the viewport to select it",
                      scene.objects.size(), scene.materials.size());
  const std::filesystem::path folder = scene_folder(scene.path, view.screenshot_dir);
  if (ImGui::Button("Open scene...")) browser.show(BrowsePurpose::open_scene, folder, "");
  ImGui::SameLine();
  if (ImGui::Button("Add model...")) browser.show(BrowsePurpose::add_model, folder, "");
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
  ImGui::PushItemWidth(-110.0f);
  section_title("Point lights");
  draw_lights(commands, selection, view);
  section_title("Scene");
  draw_scene(commands, view, browser);
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace gloss

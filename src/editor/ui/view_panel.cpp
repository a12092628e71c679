// The View & Quality panel: view mode, exposure, heat-map scale, the document's render settings
// (scene/fields.h's render table), the preview scale, and screenshots. View settings are window
// preferences (not undone); render settings are the document's and go through commands.
#include <algorithm>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "editor/ui/app.h"
#include "editor/ui/field_widgets.h"
#include "editor/ui/panel_widgets.h"

namespace gloss {

namespace {

void draw_view_mode(App& app) {
  ViewSettings& view = app.view;
  int mode = static_cast<int>(view.mode);
  ImGui::RadioButton("render (1)", &mode, static_cast<int>(ViewMode::render));
  ImGui::SameLine();
  ImGui::RadioButton("terms 2x2 (2)", &mode, static_cast<int>(ViewMode::terms));
  ImGui::RadioButton("one term (3)", &mode, static_cast<int>(ViewMode::single));
  ImGui::SameLine();
  ImGui::RadioButton("A/B Phong|Blinn (4)", &mode, static_cast<int>(ViewMode::ab));
  ImGui::RadioButton("BRDF lobe (5)", &mode, static_cast<int>(ViewMode::lobe));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the selected material's lobe as a polar plot");
  ImGui::SameLine();
  ImGui::Checkbox("pixel inspector (I)", &view.show_inspector);
  view.mode = static_cast<ViewMode>(mode);
  if (view.mode == ViewMode::single) {
    if (ImGui::BeginCombo("term", display_name(view.single))) {
      for (TermView t : {TermView::emissive_ambient, TermView::emissive, TermView::ambient,
                         TermView::diffuse, TermView::specular, TermView::total}) {
        if (ImGui::Selectable(display_name(t), t == view.single)) view.single = t;
      }
      ImGui::EndCombo();
    }
  }
  if (view.mode == ViewMode::ab) {
    ImGui::Checkbox("automatic heat scale", &view.heat_auto_scale);
    if (!view.heat_auto_scale) {
      ImGui::SliderFloat("heat scale", &view.heat_scale, 1e-4f, 10.0f, "%.4f",
                         ImGuiSliderFlags_Logarithmic);
      view.heat_scale = std::max(view.heat_scale, 1e-6f);
    }
    ImGui::Checkbox("B uses 4x exponents", &view.keep_highlight_size);
  }
  ImGui::SliderFloat("exposure", &view.exposure, -8.0f, 8.0f, "%+.2f stops");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("display value = linear x 2^exposure");
  ImGui::SameLine();
  if (ImGui::SmallButton("0")) view.exposure = 0.0f;
}

void draw_quality(App& app) {
  const Scene& scene = app.commands.scene();
  // Every render setting of the document, its encoding included (exports and the viewport
  // follow it), but the model: the Material panel's switch can rescale exponents with it.
  RenderSettings edited = scene.render;
  for (const Field<RenderSettings>& field : render_fields()) {
    if (std::string(field.key) != "model") field_widget(field, edited);
  }
  if (auto command = field_command(FieldPart::render, 0, render_fields(), scene.render, edited)) {
    execute(app, *command);
  }
  ImGui::SliderFloat("preview scale", &app.view.preview_scale, 0.25f, 1.0f, "%.2f");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("render pixels per screen pixel in the viewport");
  ImGui::TextDisabled("exports render at %d x %d, %d spp", scene.render.width, scene.render.height,
                      scene.render.spp);
  if (ImGui::Button(app.show_quality ? "Hide speed / accuracy" : "Speed / accuracy...")) {
    app.show_quality = !app.show_quality;
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("measure what each quality knob costs and buys for this scene");
  }
}

void draw_screenshot(App& app) {
  int kind = static_cast<int>(app.view.screenshot_kind);
  ImGui::RadioButton("viewport", &kind, static_cast<int>(ScreenshotKind::viewport));
  ImGui::SameLine();
  ImGui::RadioButton("term sheet", &kind, static_cast<int>(ScreenshotKind::terms));
  ImGui::SameLine();
  ImGui::RadioButton("window", &kind, static_cast<int>(ScreenshotKind::window));
  app.view.screenshot_kind = static_cast<ScreenshotKind>(kind);
  ImGui::InputText("folder", &app.view.screenshot_dir);
  if (ImGui::Button("Save screenshot (Ctrl+S)")) {
    start_screenshot(app, app.view.screenshot_kind, "", false);
  }
}

}  // namespace

void draw_view_panel(App& app, ImVec2 pos, ImVec2 size) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
  if (!ImGui::Begin("View & Quality", nullptr, flags)) {
    ImGui::End();
    return;
  }
  ImGui::PushItemWidth(-110.0f);
  section_title("View");
  draw_view_mode(app);
  section_title("Quality");
  draw_quality(app);
  section_title("Screenshot");
  draw_screenshot(app);
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace gloss

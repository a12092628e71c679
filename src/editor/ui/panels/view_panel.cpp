// The View & Quality panel: view mode, the display transform (exposure, tone curve, encoding),
// heat-map scale, the renderer and the raster path's knobs (issue 12), the document's render
// settings (scene/fields/fields.h's render table), the preview scale, and screenshots. View
// settings are window preferences (not undone); render settings are the document's and go through
// commands.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "editor/model/script/script_runner.h"
#include "editor/ui/panels/field_widgets.h"
#include "editor/ui/panels/panel_widgets.h"
#include "editor/ui/panels/panels.h"
#include "editor/ui/parts/commands.h"
#include "editor/ui/parts/exports.h"
#include "editor/ui/parts/open_windows.h"
#include "editor/ui/viewport/viewport.h"

namespace gloss {

namespace {

// The histogram of the live image as displayed (the display transform applied): R, G and B
// counts over 64 bins, drawn as lines on a square-root scale so that the dark bins of a mostly
// black background do not flatten the rest. Then the clipped share and the overlay switch.
void draw_histogram(Viewport& viewport, ViewSettings& view, const DisplayTransform& display) {
  const ExposureHistogram h = viewport.histogram(view, display);
  const float width = ImGui::GetContentRegionAvail().x;
  const float height = 56.0f;
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  ImGui::Dummy(ImVec2(width, height));
  ImDrawList* list = ImGui::GetWindowDrawList();
  list->AddRectFilled(p0, ImVec2(p0.x + width, p0.y + height), IM_COL32(20, 20, 22, 255));
  std::uint32_t top = 1;
  for (const auto& channel : h.counts) {
    for (std::uint32_t n : channel) top = std::max(top, n);
  }
  const ImU32 colours[3] = {IM_COL32(235, 80, 80, 220), IM_COL32(90, 220, 90, 220),
                            IM_COL32(100, 140, 255, 220)};
  for (int c = 0; c < 3; ++c) {
    ImVec2 points[ExposureHistogram::kBins];
    for (int b = 0; b < ExposureHistogram::kBins; ++b) {
      const float share = std::sqrt(static_cast<float>(h.counts[c][b]) / static_cast<float>(top));
      points[b] = ImVec2(p0.x + width * (static_cast<float>(b) + 0.5f) / ExposureHistogram::kBins,
                         p0.y + height - 1.0f - share * (height - 2.0f));
    }
    list->AddPolyline(points, ExposureHistogram::kBins, colours[c], 0, 1.0f);
  }
  const double share = h.clipped_share();
  const ImVec4 colour = share > 0.01 ? ImVec4(1.0f, 0.55f, 0.35f, 1.0f)
                                     : ImGui::GetStyle().Colors[ImGuiCol_TextDisabled];
  ImGui::TextColored(colour, "clipped %s (R %s G %s B %s)", clipped_text(share).c_str(),
                     clipped_text(h.clipped_channel_share(0)).c_str(),
                     clipped_text(h.clipped_channel_share(1)).c_str(),
                     clipped_text(h.clipped_channel_share(2)).c_str());
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "pixels with any channel above 1 after the exposure and tone curve: the display\n"
        "clamps them (counted in every pixel; histogram of the displayed values, R G B,\n"
        "square-root height)");
  }
  ImGui::Checkbox("show clipped pixels", &view.show_clipped);
}

// The document's display transform (render.exposure, render.tone, render.srgb): edits of the
// document, undone like any other, that no linear value depends on.
bool is_display_field(const char* key) {
  return std::string(key) == "exposure" || std::string(key) == "tone" || std::string(key) == "srgb";
}

void draw_display(Commands& commands) {
  const Scene& scene = commands.scene();
  RenderSettings edited = scene.render;
  for (const Field<RenderSettings>& field : render_fields()) {
    if (!is_display_field(field.key)) continue;
    ImGui::PushID(field.key);
    field_widget(field, edited);
    if (std::string(field.key) == "exposure" && scene.render.exposure != 0.0f) {
      ImGui::SameLine();
      if (ImGui::SmallButton("0")) edited.exposure = 0.0f;
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("exposure back to 0 stops");
    }
    ImGui::PopID();
  }
  if (auto command = field_command(FieldPart::render, 0, render_fields(), scene.render, edited)) {
    commands.execute(*command);
  }
}

void draw_view_mode(Commands& commands, ViewSettings& view, Viewport& viewport,
                    std::optional<Snapshot>& snapshot) {
  int mode = static_cast<int>(view.mode);
  ImGui::RadioButton("render (1)", &mode, static_cast<int>(ViewMode::render));
  same_line_if_fits(toggle_width("terms 2x2 (2)"));
  ImGui::RadioButton("terms 2x2 (2)", &mode, static_cast<int>(ViewMode::terms));
  ImGui::RadioButton("one term (3)", &mode, static_cast<int>(ViewMode::single));
  same_line_if_fits(toggle_width("A/B (4)"));
  ImGui::RadioButton("A/B (4)", &mode, static_cast<int>(ViewMode::ab));
  ImGui::RadioButton("BRDF lobe (5)", &mode, static_cast<int>(ViewMode::lobe));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the selected material's lobe as a polar plot");
  same_line_if_fits(toggle_width("pixel inspector (I)"));
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
    int source = static_cast<int>(view.ab_source);
    ImGui::RadioButton("Phong | Blinn-Phong", &source, static_cast<int>(AbSource::models));
    if (!snapshot) ImGui::BeginDisabled();
    ImGui::RadioButton("snapshot | live", &source, static_cast<int>(AbSource::snapshot));
    if (!snapshot) ImGui::EndDisabled();
    ImGui::RadioButton("ray traced | raster", &source, static_cast<int>(AbSource::cpu_gl));
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("A: the ray tracer at 1 spp (pixel centres), B: the raster path (GLSL)");
    }
    ImGui::RadioButton("per pixel | per vertex", &source, static_cast<int>(AbSource::pixel_vertex));
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("the raster path with Phong shading (A) and Gouraud shading (B)");
    }
    ImGui::RadioButton("material | reference", &source, static_cast<int>(AbSource::reference));
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "A: the materials as they are (1 spp), B: the materials that have a physical\n"
          "reference rendered by it (GGX, the reference path in double, 1 spp); set one in\n"
          "the Reference panel");
    }
    view.ab_source = static_cast<AbSource>(source);
    ImGui::Checkbox("automatic heat scale", &view.heat_auto_scale);
    if (!view.heat_auto_scale) {
      ImGui::SliderFloat("heat scale", &view.heat_scale, 1e-4f, 10.0f, "%.4f",
                         ImGuiSliderFlags_Logarithmic);
      view.heat_scale = std::max(view.heat_scale, 1e-6f);
    }
    if (view.ab_source == AbSource::models) {
      // The Material panel's setting, shown here as a reminder, not a second switch.
      ImGui::TextDisabled("B exponents %s: keep highlight size",
                          view.keep_highlight_size ? "x4" : "x1");
      if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("one setting, switched in the Material panel (Shading model)");
      }
    }
  }
  if (ImGui::Button("Snapshot (Ctrl+B)")) snapshot_and_compare(commands, snapshot, view);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("keep the current scene as A and compare it with the live scene as B");
  }
  if (snapshot) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s kept", snapshot->label.c_str());
  }
  draw_display(commands);
  draw_histogram(viewport, view, display_transform(commands.scene().render));
}

// The teapots' tessellation, the mesh resolution that per-vertex shading depends on (and the
// ray tracer's silhouettes too); shown when the document has a teapot.
void draw_tessellation(Commands& commands) {
  const Scene& scene = commands.scene();
  const auto teapot = std::find_if(scene.objects.begin(), scene.objects.end(),
                                   [](const Object& o) { return o.type == ObjectType::teapot; });
  if (teapot == scene.objects.end()) return;
  int level = teapot->params.tessellation;
  if (ImGui::SliderInt("teapot tessellation", &level, 1, 64)) {
    commands.execute(SetTessellation{level});
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "segments per patch side of every teapot: 32 x 2 x N^2 triangles.\n"
        "Low: per-vertex (Gouraud) highlights break up; raise it and they recover.");
  }
}

// The viewport's renderer and, where the raster path draws something, its knobs (issue 12).
void draw_renderer(Commands& commands, ViewSettings& view, const Viewport& viewport) {
  int renderer = static_cast<int>(view.renderer);
  ImGui::RadioButton("Ray traced", &renderer, static_cast<int>(RendererChoice::cpu));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("exact, refined pass by pass to the scene's spp");
  same_line_if_fits(toggle_width("Raster (GLSL)"));
  ImGui::RadioButton("Raster (GLSL)", &renderer, static_cast<int>(RendererChoice::gl));
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("OpenGL, one sample per pixel, shadow maps; redrawn on every change");
  }
  ImGui::RadioButton("Automatic", &renderer, static_cast<int>(RendererChoice::automatic));
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "raster while the camera or a light is dragged, where it measured no slower than the\n"
        "ray tracer (status bar: the two frame times); ray traced when still");
  }
  view.renderer = static_cast<RendererChoice>(renderer);
  if (viewport.raster_unavailable()) {
    ImGui::TextColored(ImVec4(1.0f, 0.55f, 0.35f, 1.0f), "raster unavailable: ray traced");
  }
  const bool raster_ab = view.mode == ViewMode::ab && (view.ab_source == AbSource::cpu_gl ||
                                                       view.ab_source == AbSource::pixel_vertex);
  draw_tessellation(commands);
  if (view.renderer == RendererChoice::cpu && !raster_ab) return;
  RasterSettings& raster = view.raster;
  int shading = static_cast<int>(raster.shading);
  ImGui::RadioButton("Per pixel", &shading, static_cast<int>(ShadingFrequency::pixel));
  same_line_if_fits(toggle_width("Per vertex (Gouraud)"));
  ImGui::RadioButton("Per vertex (Gouraud)", &shading, static_cast<int>(ShadingFrequency::vertex));
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "meshes lit at their vertices, the per-light weights interpolated and the shadow\n"
        "test made per pixel; spheres stay per pixel. The teapot's vertices come from its\n"
        "tessellation (the slider above).");
  }
  raster.shading = static_cast<ShadingFrequency>(shading);
  char size_text[16];
  std::snprintf(size_text, sizeof size_text, "%d", raster.shadow_map_size);
  if (ImGui::BeginCombo("shadow map", size_text)) {
    for (int size = 256; size <= 4096; size *= 2) {
      std::snprintf(size_text, sizeof size_text, "%d", size);
      if (ImGui::Selectable(size_text, size == raster.shadow_map_size)) {
        raster.shadow_map_size = size;
      }
    }
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("texels per side of each light's cube shadow map (scene shadows on)");
  }
  ImGui::DragFloat("shadow bias", &raster.shadow_bias, 0.05f, 0.0f, 16.0f, "%.2f texels");
  raster.shadow_bias = std::max(raster.shadow_bias, 0.0f);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("too small: shadow acne; too large: light leaks under contact shadows");
  }
}

void draw_quality(Commands& commands, ViewSettings& view, OpenWindows& windows) {
  const Scene& scene = commands.scene();
  // Every render setting of the document but the model (the Material panel's switch can
  // rescale exponents with it) and the display transform (the View section's).
  RenderSettings edited = scene.render;
  for (const Field<RenderSettings>& field : render_fields()) {
    if (std::string(field.key) != "model" && !is_display_field(field.key)) {
      field_widget(field, edited);
    }
  }
  if (auto command = field_command(FieldPart::render, 0, render_fields(), scene.render, edited)) {
    commands.execute(*command);
  }
  ImGui::SliderFloat("preview scale", &view.preview_scale, 0.25f, 1.0f, "%.2f");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("render pixels per screen pixel in the viewport");
  ImGui::TextDisabled("exports render at %d x %d, %d spp", scene.render.width, scene.render.height,
                      scene.render.spp);
  if (ImGui::Button(windows.quality ? "Hide speed / accuracy" : "Speed / accuracy...")) {
    windows.quality = !windows.quality;
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("measure what each quality knob costs and buys for this scene");
  }
}

void draw_screenshot(ViewSettings& view, Exports& exports) {
  int kind = static_cast<int>(view.screenshot_kind);
  ImGui::RadioButton("viewport", &kind, static_cast<int>(ScreenshotKind::viewport));
  same_line_if_fits(toggle_width("term sheet"));
  ImGui::RadioButton("term sheet", &kind, static_cast<int>(ScreenshotKind::terms));
  same_line_if_fits(toggle_width("window"));
  ImGui::RadioButton("window", &kind, static_cast<int>(ScreenshotKind::window));
  same_line_if_fits(toggle_width("as shown"));
  ImGui::RadioButton("as shown", &kind, static_cast<int>(ScreenshotKind::shown));
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("the frame on screen as it is, at its own size (not rendered again)");
  }
  same_line_if_fits(toggle_width("EXR"));
  ImGui::RadioButton("EXR", &kind, static_cast<int>(ScreenshotKind::exr));
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "the render (or the term shown) as linear 32-bit float OpenEXR, before the display\n"
        "transform, at the document's size");
  }
  view.screenshot_kind = static_cast<ScreenshotKind>(kind);
  ImGui::InputText("folder", &view.screenshot_dir);
  if (ImGui::Button("Save screenshot (Ctrl+S)")) {
    exports.start(view.screenshot_kind);
  }
}

}  // namespace

void snapshot_and_compare(Commands& commands, std::optional<Snapshot>& snapshot,
                          ViewSettings& view) {
  snapshot = take_snapshot(commands.document(), snapshot);
  view.mode = ViewMode::ab;
  view.ab_source = AbSource::snapshot;
  commands.info(snapshot->label + " taken: A shows it, B the live scene");
}

void draw_view_panel(Commands& commands, ViewSettings& view, Viewport& viewport,
                     std::optional<Snapshot>& snapshot, OpenWindows& windows, Exports& exports,
                     ImVec2 pos, ImVec2 size) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
  if (!ImGui::Begin("View & Quality", nullptr, flags)) {
    ImGui::End();
    return;
  }
  ImGui::PushItemWidth(-label_room(130.0f));  // room for "samples per pixel"
  section_title("Renderer");
  draw_renderer(commands, view, viewport);
  section_title("View");
  draw_view_mode(commands, view, viewport, snapshot);
  section_title("Quality");
  draw_quality(commands, view, windows);
  section_title("Screenshot");
  draw_screenshot(view, exports);
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace gloss

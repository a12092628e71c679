// The main menu bar: File, Edit, View, Help. Items call the same actions as the shortcuts.
#include <imgui.h>

#include "editor/ui/app.h"

namespace gloss {

namespace {

std::filesystem::path scene_folder(const App& app) {
  const std::string& path = app.commands.scene().path;
  return path.empty() ? std::filesystem::path(app.view.screenshot_dir)
                      : std::filesystem::path(path).parent_path();
}

void file_menu(App& app) {
  if (!ImGui::BeginMenu("File")) return;
  if (ImGui::MenuItem("Open scene...", "Ctrl+O")) {
    app.browser.show(BrowsePurpose::open_scene, scene_folder(app), "");
  }
  if (ImGui::BeginMenu("Open recent", !app.recent.scenes.paths.empty())) {
    std::string chosen;  // opening reorders the list: act after the loop
    for (const std::string& path : app.recent.scenes.paths) {
      if (ImGui::MenuItem(path.c_str())) chosen = path;
    }
    if (!chosen.empty()) {
      try {
        request_open_scene(app, chosen);
      } catch (const std::exception& e) {
        app.notices.error(e.what(), app.now_s());
      }
    }
    ImGui::EndMenu();
  }
  if (ImGui::MenuItem("Add model...")) {
    app.browser.show(BrowsePurpose::add_model, scene_folder(app), "");
  }
  ImGui::Separator();
  const std::string& path = app.commands.scene().path;
  if (ImGui::MenuItem("Save scene", "Ctrl+Shift+S", false, !path.empty())) {
    try {
      save_scene_as(app, path);
    } catch (const std::exception& e) {
      app.notices.error(e.what(), app.now_s());
    }
  }
  if (ImGui::MenuItem("Save scene as...")) {
    app.browser.show(BrowsePurpose::save_scene, scene_folder(app),
                     path.empty() ? "scene.json" : std::filesystem::path(path).filename().string());
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Load materials (JSON, MTL)...")) {
    app.browser.show(BrowsePurpose::load_materials, scene_folder(app), "");
  }
  if (ImGui::MenuItem("Save materials (JSON, MTL)...")) {
    app.browser.show(BrowsePurpose::save_materials, scene_folder(app), "materials.mtl");
  }
  if (ImGui::MenuItem("Export GLSL...")) {
    app.browser.show(BrowsePurpose::export_glsl, scene_folder(app), "gloss.frag");
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Screenshot", "Ctrl+S")) {
    start_screenshot(app, app.view.screenshot_kind, "", false);
  }
  if (ImGui::MenuItem("Screenshot: viewport render")) {
    start_screenshot(app, ScreenshotKind::viewport, "", false);
  }
  if (ImGui::MenuItem("Screenshot: term sheet")) {
    start_screenshot(app, ScreenshotKind::terms, "", false);
  }
  if (ImGui::MenuItem("Screenshot: frame as shown")) {
    start_screenshot(app, ScreenshotKind::shown, "", false);
  }
  if (ImGui::MenuItem("Screenshot: whole window")) {
    start_screenshot(app, ScreenshotKind::window, "", false);
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Quit", "Ctrl+Q")) request_quit(app);
  ImGui::EndMenu();
}

void edit_menu(App& app) {
  if (!ImGui::BeginMenu("Edit")) return;
  const std::string undo_text = "Undo " + app.commands.undo_label();
  const std::string redo_text = "Redo " + app.commands.redo_label();
  if (ImGui::MenuItem(undo_text.c_str(), "Ctrl+Z", false, app.commands.can_undo())) undo(app);
  if (ImGui::MenuItem(redo_text.c_str(), "Ctrl+Shift+Z", false, app.commands.can_redo())) {
    redo(app);
  }
  ImGui::TextDisabled("%zu undo / %zu redo steps", app.commands.undo_count(),
                      app.commands.redo_count());
  ImGui::EndMenu();
}

void view_menu(App& app) {
  if (!ImGui::BeginMenu("View")) return;
  ViewSettings& view = app.view;
  if (ImGui::MenuItem("Render", "1", view.mode == ViewMode::render)) view.mode = ViewMode::render;
  if (ImGui::MenuItem("Terms 2x2", "2", view.mode == ViewMode::terms)) view.mode = ViewMode::terms;
  if (ImGui::BeginMenu("One term")) {
    for (TermView t : {TermView::emissive_ambient, TermView::emissive, TermView::ambient,
                       TermView::diffuse, TermView::specular, TermView::total}) {
      if (ImGui::MenuItem(display_name(t), nullptr,
                          view.mode == ViewMode::single && view.single == t)) {
        view.mode = ViewMode::single;
        view.single = t;
      }
    }
    ImGui::EndMenu();
  }
  if (ImGui::MenuItem("A/B Phong vs Blinn-Phong", "4",
                      view.mode == ViewMode::ab && view.ab_source == AbSource::models)) {
    view.mode = ViewMode::ab;
    view.ab_source = AbSource::models;
  }
  if (ImGui::MenuItem("BRDF lobe of the selected material", "5", view.mode == ViewMode::lobe)) {
    view.mode = ViewMode::lobe;
  }
  ImGui::MenuItem("Pixel inspector", "I", &view.show_inspector);
  if (ImGui::MenuItem("Snapshot, then A/B snapshot vs live", "Ctrl+B")) snapshot_and_compare(app);
  if (ImGui::MenuItem("A/B snapshot vs live", nullptr,
                      view.mode == ViewMode::ab && view.ab_source == AbSource::snapshot,
                      app.snapshot.has_value())) {
    view.mode = ViewMode::ab;
    view.ab_source = AbSource::snapshot;
  }
  // The GLSL path (issue 12): the two A/B comparisons the raster path adds.
  if (ImGui::MenuItem("A/B ray traced vs raster (GLSL)", nullptr,
                      view.mode == ViewMode::ab && view.ab_source == AbSource::cpu_gl)) {
    view.mode = ViewMode::ab;
    view.ab_source = AbSource::cpu_gl;
  }
  if (ImGui::MenuItem("A/B raster per pixel vs per vertex", nullptr,
                      view.mode == ViewMode::ab && view.ab_source == AbSource::pixel_vertex)) {
    view.mode = ViewMode::ab;
    view.ab_source = AbSource::pixel_vertex;
  }
  ImGui::MenuItem("Show clipped pixels", nullptr, &view.show_clipped);
  ImGui::Separator();
  const bool srgb = app.commands.scene().render.srgb;
  if (ImGui::MenuItem("sRGB display encoding", nullptr, srgb)) {
    execute(app, SetField{FieldPart::render, 0, "srgb", number_value(!srgb)});
  }
  if (ImGui::MenuItem("Reset exposure")) view.exposure = 0.0f;
  ImGui::MenuItem("Orbit light", nullptr, &view.orbit_light);
  ImGui::MenuItem("Quality: speed / accuracy", nullptr, &app.show_quality);
  ImGui::EndMenu();
}

}  // namespace

void draw_menu_bar(App& app) {
  if (!ImGui::BeginMainMenuBar()) return;
  file_menu(app);
  edit_menu(app);
  view_menu(app);
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("Help and shortcuts", "F1")) app.show_help = true;
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

}  // namespace gloss

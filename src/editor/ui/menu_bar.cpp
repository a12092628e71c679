// The main menu bar: File, Edit, Object, View, Help. Items call the same actions as the shortcuts.
#include <algorithm>
#include <filesystem>

#include <imgui.h>

#include "editor/model/document/new_objects.h"
#include "editor/model/session/file_defaults.h"
#include "editor/ui/panels/panels.h"
#include "editor/ui/parts/commands.h"
#include "editor/ui/parts/exports.h"
#include "editor/ui/parts/file_actions.h"
#include "editor/ui/parts/layout_state.h"
#include "editor/ui/parts/open_windows.h"
#include "editor/ui/parts/selection.h"
#include "editor/ui/parts/session.h"

namespace gloss {

namespace {

void file_menu(Commands& commands, const Selection& selection, Session& session, FileActions& files,
               Exports& exports, const ViewSettings& view) {
  if (!ImGui::BeginMenu("File")) return;
  // A reference: it follows the document when Open recent replaces it.
  const std::string& path = commands.scene().path;
  FileBrowser& browser = session.browser;
  if (ImGui::MenuItem("Open scene...", "Ctrl+O"))
    browser.start(BrowsePurpose::open_scene, path, "");
  if (ImGui::BeginMenu("Open recent", !session.recent.scenes.paths.empty())) {
    std::string chosen;  // opening reorders the list: act after the loop
    for (const std::string& recent : session.recent.scenes.paths) {
      if (ImGui::MenuItem(recent.c_str())) chosen = recent;
    }
    if (!chosen.empty()) {
      try {
        files.request_open_scene(chosen);
      } catch (const std::exception& e) {
        commands.error(e.what());
      }
    }
    ImGui::EndMenu();
  }
  if (ImGui::MenuItem("Add model...")) browser.start(BrowsePurpose::add_model, path, "");
  ImGui::Separator();
  // A shipped scene is never saved over: Save asks for a name in the user's folder (Save as).
  const bool own_file = saves_in_place(path);
  if (ImGui::MenuItem("Save scene", "Ctrl+Shift+S", false, own_file)) {
    try {
      files.save_scene_as(path);
    } catch (const std::exception& e) {
      commands.error(e.what());
    }
  }
  if (!own_file && !path.empty() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    ImGui::SetTooltip("%s is a scene gloss ships: use Save scene as", path.c_str());
  }
  if (ImGui::MenuItem("Save scene as...")) {
    browser.start(BrowsePurpose::save_scene, path, scene_file_name(path));
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Load materials (JSON, MTL)...")) {
    browser.start(BrowsePurpose::load_materials, path, "");
  }
  const Scene& scene = commands.scene();
  if (ImGui::MenuItem("Save the selected material...")) {
    browser.start(BrowsePurpose::save_material, path,
                  suggested_file_name(scene, selection.object, "save-material"));
  }
  if (ImGui::MenuItem("Save all materials (JSON, MTL)...")) {
    browser.start(BrowsePurpose::save_materials, path,
                  suggested_file_name(scene, selection.object, "save-materials"));
  }
  if (ImGui::MenuItem("Export GLSL...")) {
    browser.start(BrowsePurpose::export_glsl, path,
                  suggested_file_name(scene, selection.object, "export-glsl"));
  }
  if (ImGui::MenuItem("Export glTF...")) {
    browser.show(BrowsePurpose::export_gltf, scene_folder(path, view.screenshot_dir), "scene.glb");
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Screenshot", "Ctrl+S")) exports.start(view.screenshot_kind);
  if (ImGui::MenuItem("Screenshot: viewport render")) exports.start(ScreenshotKind::viewport);
  if (ImGui::MenuItem("Screenshot: term sheet")) exports.start(ScreenshotKind::terms);
  if (ImGui::MenuItem("Screenshot: frame as shown")) exports.start(ScreenshotKind::shown);
  if (ImGui::MenuItem("Screenshot: whole window")) exports.start(ScreenshotKind::window);
  if (ImGui::MenuItem("Screenshot: linear EXR")) exports.start(ScreenshotKind::exr);
  ImGui::Separator();
  if (ImGui::MenuItem("Quit", "Ctrl+Q")) files.request_quit();
  ImGui::EndMenu();
}

// The Object menu: add a primitive or a model, and what the Outliner's buttons and keys do to
// the selection; the gizmo's mode.
void object_menu(Commands& commands, Selection& selection, ViewSettings& view,
                 FileBrowser& browser) {
  if (!ImGui::BeginMenu("Object")) return;
  const Scene& scene = commands.scene();
  const int count = static_cast<int>(scene.objects.size());
  if (ImGui::BeginMenu("Add")) {
    const ObjectType types[4] = {ObjectType::sphere, ObjectType::quad, ObjectType::box,
                                 ObjectType::teapot};
    const char* labels[4] = {"Sphere", "Quad", "Box", "Teapot"};
    for (int t = 0; t < 4; ++t) {
      if (ImGui::MenuItem(labels[t]) && commands.execute(primitive_objects(scene, types[t]))) {
        select_only(selection, count);
      }
    }
    if (ImGui::MenuItem("Model from a file..."))
      browser.start(BrowsePurpose::add_model, scene.path, "");
    ImGui::EndMenu();
  }
  const std::vector<int> objects = selected_objects(selection, count);
  const bool any = !objects.empty();
  ImGui::Separator();
  if (ImGui::MenuItem("Frame selection", "F", false, any)) frame_selection(commands, selection);
  if (ImGui::MenuItem("Duplicate", "Ctrl+D", false, any) &&
      commands.execute(DuplicateObjects{objects})) {
    std::vector<int> copies;
    for (std::size_t k = 0; k < objects.size(); ++k) copies.push_back(count + int(k));
    select_all_of(selection, copies);
  }
  if (ImGui::MenuItem("Delete", "Del", false, any) && commands.execute(DeleteObjects{objects})) {
    select_only(selection, std::max(objects.front() - 1, 0));
  }
  if (ImGui::MenuItem("Hide", "H", false, any)) commands.execute(SetHidden{objects, true});
  if (ImGui::MenuItem("Solo", "Shift+H", false, any)) commands.execute(SoloObjects{objects});
  if (ImGui::MenuItem("Show all", "Alt+H", false, count > 0)) {
    std::vector<int> all;
    for (int i = 0; i < count; ++i) all.push_back(i);
    commands.execute(SetHidden{all, false});
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Move", "W", view.gizmo == GizmoMode::move)) view.gizmo = GizmoMode::move;
  if (ImGui::MenuItem("Rotate", "E", view.gizmo == GizmoMode::rotate))
    view.gizmo = GizmoMode::rotate;
  if (ImGui::MenuItem("Scale", "R", view.gizmo == GizmoMode::scale)) view.gizmo = GizmoMode::scale;
  ImGui::MenuItem("Show the gizmo", nullptr, &view.show_gizmo);
  ImGui::TextDisabled("drag a handle; Ctrl snaps");
  ImGui::EndMenu();
}

void edit_menu(Commands& commands) {
  if (!ImGui::BeginMenu("Edit")) return;
  const CommandLayer& history = commands.document();
  const std::string undo_text = "Undo " + history.undo_label();
  const std::string redo_text = "Redo " + history.redo_label();
  if (ImGui::MenuItem(undo_text.c_str(), "Ctrl+Z", false, history.can_undo())) commands.undo();
  if (ImGui::MenuItem(redo_text.c_str(), "Ctrl+Shift+Z", false, history.can_redo())) {
    commands.redo();
  }
  ImGui::TextDisabled("%zu undo / %zu redo steps", history.undo_count(), history.redo_count());
  ImGui::EndMenu();
}

void view_menu(Commands& commands, ViewSettings& view, std::optional<Snapshot>& snapshot,
               OpenWindows& windows) {
  if (!ImGui::BeginMenu("View")) return;
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
  // Every object with the checker on its (u, v); the document keeps its materials.
  ImGui::MenuItem("UV checker", nullptr, &view.uv_checker);
  if (ImGui::MenuItem("Snapshot, then A/B snapshot vs live", "Ctrl+B")) {
    snapshot_and_compare(commands, snapshot, view);
  }
  if (ImGui::MenuItem("A/B snapshot vs live", nullptr,
                      view.mode == ViewMode::ab && view.ab_source == AbSource::snapshot,
                      snapshot.has_value())) {
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
  // Issue 23: the material beside its physical reference.
  if (ImGui::MenuItem("A/B material vs physical reference", nullptr,
                      view.mode == ViewMode::ab && view.ab_source == AbSource::reference)) {
    view.mode = ViewMode::ab;
    view.ab_source = AbSource::reference;
  }
  ImGui::MenuItem("Show clipped pixels", nullptr, &view.show_clipped);
  ImGui::Separator();
  const bool srgb = commands.scene().render.srgb;
  if (ImGui::MenuItem("sRGB display encoding", nullptr, srgb)) {
    commands.execute(SetField{FieldPart::render, 0, "srgb", number_value(!srgb)});
  }
  if (ImGui::BeginMenu("Tone curve")) {
    const ToneCurve tone = commands.scene().render.tone;
    for (ToneCurve t : {ToneCurve::none, ToneCurve::reinhard, ToneCurve::aces}) {
      if (ImGui::MenuItem(to_string(t), nullptr, t == tone) && t != tone) {
        commands.execute(SetField{FieldPart::render, 0, "tone", number_value(static_cast<int>(t))});
      }
    }
    ImGui::EndMenu();
  }
  if (ImGui::MenuItem("Reset exposure", nullptr, false, commands.scene().render.exposure != 0.0f)) {
    commands.execute(SetField{FieldPart::render, 0, "exposure", number_value(0.0)});
  }
  ImGui::MenuItem("Orbit light", nullptr, &view.orbit_light);
  ImGui::MenuItem("Quality: speed / accuracy", nullptr, &windows.quality);
  ImGui::EndMenu();
}

// Where the panels are: collapsed to strips, or hidden behind a maximised viewport.
void panels_menu(LayoutState& layout) {
  if (!ImGui::BeginMenu("Panels")) return;
  PanelChoices& p = layout.panels;
  ImGui::MenuItem("Maximise the viewport", "Ctrl+Space", &p.viewport_maximised);
  bool left = !p.left_collapsed, right = !p.right_collapsed;
  if (ImGui::MenuItem("Material", "[", &left)) {
    p.left_collapsed = !left;
    p.viewport_maximised = false;
  }
  if (ImGui::MenuItem("Outliner, Lights & Scene, View & Quality", "]", &right)) {
    p.right_collapsed = !right;
    p.viewport_maximised = false;
  }
  if (ImGui::MenuItem("Reset the layout")) layout.panels = PanelChoices{};
  ImGui::EndMenu();
}

}  // namespace

void draw_menu_bar(Commands& commands, Selection& selection, ViewSettings& view,
                   std::optional<Snapshot>& snapshot, Session& session, FileActions& files,
                   Exports& exports, OpenWindows& windows, LayoutState& layout) {
  if (!ImGui::BeginMainMenuBar()) return;
  file_menu(commands, selection, session, files, exports, view);
  edit_menu(commands);
  object_menu(commands, selection, view, session.browser);
  view_menu(commands, view, snapshot, windows);
  panels_menu(layout);
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("Help and shortcuts", "F1")) windows.help = true;
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

}  // namespace gloss

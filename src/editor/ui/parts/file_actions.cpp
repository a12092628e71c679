// File and session actions of the editor: opening and saving scenes and materials, adding
// models, the GLSL export, recovery and quitting. Errors propagate as InputError /
// RuntimeFailure for the UI to show.
#include "editor/ui/parts/file_actions.h"

#include <algorithm>
#include <limits>

#include "base/error.h"
#include "base/text/ascii.h"
#include "editor/model/document/document.h"
#include "editor/model/document/new_objects.h"
#include "editor/model/export/glsl_export.h"
#include "editor/model/export/gltf_file.h"
#include "editor/model/session/file_defaults.h"
#include "editor/model/session/material_library_folder.h"
#include "editor/ui/parts/commands.h"
#include "editor/ui/parts/material_library.h"
#include "editor/ui/parts/open_windows.h"
#include "editor/ui/parts/run_state.h"
#include "editor/ui/parts/selection.h"
#include "editor/ui/parts/session.h"
#include "io/scene/material_maps.h"
#include "io/scene/scene_loader.h"

namespace gloss {

namespace {

bool has_extension(const std::string& path, const char* extension) {
  return lower_extension(path) == extension;
}

}  // namespace

void FileActions::remember_recent(RecentKind kind, const std::string& path) {
  m_session.recent.of(kind).add(path);
  try {
    save_recent_files(m_session.recent.of(kind), m_session.config_folder / recent_file_name(kind));
  } catch (const std::exception& e) {
    m_commands.error(std::string("cannot save the recent files: ") + e.what());
  }
}

void FileActions::open_scene(const std::string& requested) {
  const std::string path = requested;  // may refer into the recent list, which changes below
  std::vector<std::string> warnings;
  open_loaded(std::make_shared<Scene>(load_scene(path, &warnings)), path, warnings);
}

void FileActions::open_loaded(std::shared_ptr<const Scene> scene, const std::string& path,
                              const std::vector<std::string>& warnings) {
  // Undoing the open gives back the earlier document with its own saved/unsaved state.
  m_document.open_document(std::move(scene),
                           "open " + std::filesystem::path(path).filename().string());
  select_only(m_selection, 0);
  m_selection.light = 0;
  remember_recent(RecentKind::scene, path);
  for (const std::string& w : warnings) m_commands.info("warning: " + w);
  m_commands.info("opened " + path);
}

void FileActions::request_open_scene(const std::string& requested) {
  const std::string path = requested;
  // Read before asking: a file that does not read is refused here, with the edits untouched
  // and no question about them.
  std::vector<std::string> warnings;
  auto scene = std::make_shared<Scene>(load_scene(path, &warnings));
  // Scripts answer no questions; they replace the document as they say.
  if (m_session.unsaved.request_open(path, m_document.dirty() && !m_run.script)) {
    open_loaded(scene, path, warnings);
    return;
  }
  m_session.pending_open = scene;
  m_session.pending_warnings = warnings;
}

void FileActions::add_model(const std::string& path) {
  // Scaled to the scene, set down on the surface below, beside the objects there (new_objects.h).
  std::vector<std::string> warnings, notes;
  const AddObjects add = model_objects(m_document.scene(), path, &warnings, &notes);
  const int first_new = static_cast<int>(m_document.scene().objects.size());
  m_document.execute(add);
  m_document.seal();
  std::vector<int> added;
  for (int i = first_new; i < static_cast<int>(m_document.scene().objects.size()); ++i) {
    added.push_back(i);
  }
  select_all_of(m_selection, added);
  remember_recent(RecentKind::model, path);
  for (const std::string& w : warnings) m_commands.info("warning: " + w);
  // glTF materials read as the fitted Phong (or assimp's rule), with both errors.
  for (const std::string& n : notes) m_commands.info(n);
  m_commands.info("added " + std::to_string(add.objects.size()) + " object(s) from " + path);
}

void FileActions::save_scene_as(const std::string& requested) {
  const std::string path = requested;  // may refer into the document, which changes below
  // The last guard: no caller writes over a scene gloss ships (the panels offer Save as).
  if (const std::string refusal = shipped_scene_refusal(path); !refusal.empty()) {
    throw std::runtime_error(refusal);
  }
  save_scene(m_document.scene(), path);  // relative file names follow the new folder
  m_document.set_path(path);
  m_document.mark_saved();
  remember_recent(RecentKind::scene, path);
  m_commands.info("saved scene " + path);
}

void FileActions::load_materials(const std::string& path) {
  std::vector<NamedMaterial> materials =
      has_extension(path, ".mtl") ? load_mtl(path) : load_materials_json(path);
  if (materials.empty()) throw InputError(path, "the file holds no materials");
  m_library.loaded = std::move(materials);
  m_library.loaded_from = std::filesystem::path(path).filename().string();
  remember_recent(RecentKind::materials, path);
  m_commands.info("loaded " + std::to_string(m_library.loaded.size()) + " material(s) from " +
                  path + "; apply them in the Material panel");
}

void FileActions::save_materials(const std::string& path) {
  const Scene& scene = m_document.scene();
  std::vector<NamedMaterial> materials;
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const std::string name =
        i < scene.material_names.size() ? scene.material_names[i] : "material" + std::to_string(i);
    materials.emplace_back(name, scene.materials[i]);
  }
  if (has_extension(path, ".mtl")) {
    save_mtl(path, materials);
  } else {
    save_materials_json(path, materials);
  }
  m_commands.info("saved " + std::to_string(materials.size()) + " material(s) to " + path);
}

void FileActions::save_selected_material(const std::string& path) {
  const Scene& scene = m_document.scene();
  if (scene.objects.empty()) throw std::runtime_error("the scene has no object to take it from");
  const int i = std::clamp(m_selection.object, 0, static_cast<int>(scene.objects.size()) - 1);
  const int m = scene.objects[static_cast<std::size_t>(i)].material;
  const std::vector<NamedMaterial> one = {{scene.material_names.at(m), scene.materials.at(m)}};
  if (has_extension(path, ".mtl")) {
    save_mtl(path, one);
  } else {
    save_materials_json(path, one);
  }
  m_commands.info("saved material '" + one[0].first + "' to " + path);
}

void FileActions::save_to_library() {
  const Scene& scene = m_document.scene();
  if (scene.objects.empty()) return;
  const int i = std::clamp(m_selection.object, 0, static_cast<int>(scene.objects.size()) - 1);
  const int m = scene.objects[static_cast<std::size_t>(i)].material;
  const std::string name = scene.material_names.at(m);
  const std::string path = gloss::save_to_library(m_library.folder, name, scene.materials.at(m));
  reload_library();
  m_commands.info("saved '" + name + "' to your library: " + path);
}

void FileActions::reload_library() {
  std::vector<std::string> errors;
  m_library.user = read_library(m_library.folder, &errors);
  for (const std::string& e : errors) m_commands.error("library: " + e);
}

void FileActions::export_glsl_shader(const std::string& path) {
  const Scene& scene = m_document.scene();
  const int selected = m_selection.object;
  if (selected < 0 || selected >= static_cast<int>(scene.objects.size())) {
    throw std::runtime_error("select an object to export its material");
  }
  const int material = scene.objects[static_cast<std::size_t>(selected)].material;
  write_glsl_export(path, scene, material);
  m_commands.info("exported the GLSL shader of " + object_label(scene, selected) + " to " + path);
}

void FileActions::export_gltf_scene(const std::string& path) {
  m_commands.info(write_gltf_file(m_document.scene(), path, false));
}

void FileActions::load_map(int object, MapSlot slot, const std::string& path) {
  const Scene& scene = m_document.scene();
  if (object < 0 || object >= static_cast<int>(scene.objects.size())) {
    throw std::runtime_error("select an object to load a map into its material");
  }
  const Material& material = scene.materials.at(
      static_cast<std::size_t>(scene.objects[static_cast<std::size_t>(object)].material));
  TextureMap map = material.map(slot);  // its settings stay
  map.file = std::filesystem::absolute(path).lexically_normal().string();
  map.texture = nullptr;
  read_map(map, slot, MapReadContext{});                  // throws InputError naming the file
  const std::string label = object_label(scene, object);  // before the scene changes
  if (!m_commands.execute(SetField{FieldPart::material, object, map_key(slot), map_value(map)})) {
    throw std::runtime_error("the map could not be set (see the notices)");
  }
  remember_recent(RecentKind::maps, path);
  m_commands.info("loaded " + path + " as the " + to_string(slot) + " map of " + label);
}

void FileActions::browser_action(const std::string& path) {
  FileBrowser& browser = m_session.browser;
  try {
    switch (browser.purpose) {
      case BrowsePurpose::open_scene:
        request_open_scene(path);
        break;
      case BrowsePurpose::add_model:
        add_model(path);
        break;
      case BrowsePurpose::load_materials:
        load_materials(path);
        break;
      case BrowsePurpose::save_scene:
        save_scene_as(path);
        break;
      case BrowsePurpose::save_materials:
        save_materials(path);
        break;
      case BrowsePurpose::save_material:
        save_selected_material(path);
        break;
      case BrowsePurpose::export_glsl:
        export_glsl_shader(path);
        break;
      case BrowsePurpose::export_gltf:
        export_gltf_scene(path);
        break;
      case BrowsePurpose::load_map:
        load_map(browser.map_target.object, browser.map_target.slot, path);
        break;
      case BrowsePurpose::open_environment:
        // The command reads the map; a bad file throws (the panel shows why) and the scene
        // keeps what it had.
        m_document.execute(SetEnvironment{path});
        m_commands.info("environment " + path);
        break;
    }
    browser.open = false;
    save_last_folder(m_session.config_folder, browser.last_folder);
  } catch (const std::exception& e) {
    // The action failed before touching the document; the panel stays open with the reason.
    browser.error = e.what();
    browser.confirm_replace.clear();
  }
}

void FileActions::recover() {
  if (!m_session.offered_recovery) return;
  const Recovery& r = *m_session.offered_recovery;
  m_document.reset(r.scene, false);
  select_only(m_selection, std::max(0, r.selected_object));
  m_commands.info("recovered the autosaved session");
  m_session.offered_recovery.reset();
}

void FileActions::discard_recovery() {
  if (m_session.autosaver) m_session.autosaver->discard();
  m_session.offered_recovery.reset();
}

void FileActions::request_quit() {
  if (m_document.dirty() && !m_run.script) {
    m_windows.quit_question = true;
  } else {
    m_run.quit = true;
  }
}

}  // namespace gloss

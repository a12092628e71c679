// File and session actions of the editor: opening and saving scenes and materials, adding
// models, the GLSL export, recovery and quitting. Errors propagate as InputError /
// RuntimeFailure for the UI to show.
#include "editor/ui/parts/file_actions.h"

#include <algorithm>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "base/error.h"
#include "editor/model/document/document.h"
#include "editor/model/export/glsl_export.h"
#include "editor/model/export/gltf_file.h"
#include "editor/ui/parts/commands.h"
#include "editor/ui/parts/material_library.h"
#include "editor/ui/parts/open_windows.h"
#include "editor/ui/parts/run_state.h"
#include "editor/ui/parts/selection.h"
#include "editor/ui/parts/session.h"
#include "io/model/model_loader.h"
#include "io/scene/material_maps.h"
#include "io/scene/scene_loader.h"

namespace gloss {

namespace {

bool has_extension(const std::string& path, const char* extension) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == extension;
}

std::string unique_material_name(const Scene& scene, const std::string& wanted) {
  std::string name = wanted.empty() ? std::string("material") : wanted;
  for (int n = 2; find_material(scene, name) >= 0; ++n) name = wanted + "_" + std::to_string(n);
  return name;
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
  auto scene = std::make_shared<Scene>(load_scene(path, &warnings));
  // Undoing the open gives back the earlier document with its own saved/unsaved state.
  m_document.open_document(scene, "open " + std::filesystem::path(path).filename().string());
  m_selection.object = 0;
  m_selection.light = 0;
  remember_recent(RecentKind::scene, path);
  for (const std::string& w : warnings) m_commands.info("warning: " + w);
  m_commands.info("opened " + path);
}

void FileActions::request_open_scene(const std::string& path) {
  // Scripts answer no questions; they replace the document as they say.
  if (m_session.unsaved.request_open(path, m_document.dirty() && !m_run.script)) open_scene(path);
}

void FileActions::add_model(const std::string& path) {
  const Model model = load_model(path);
  // Fit the model into a 2-unit box centred on the camera target.
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const ModelPart& part : model.parts) {
    glm::vec3 a, b;
    if (!mesh_bounds(part.mesh, a, b)) continue;
    lo = glm::min(lo, a);
    hi = glm::max(hi, b);
  }
  if (!(lo.x <= hi.x)) throw InputError(path, "the model has no vertices");
  const glm::vec3 extent = hi - lo;
  const float size = std::max(extent.x, std::max(extent.y, extent.z));
  const float scale = size > 0.0f ? 2.0f / size : 1.0f;

  auto scene = std::make_shared<Scene>(m_document.scene());
  const glm::vec3 position = scene->camera.target - (lo + hi) * 0.5f * scale;
  // The scene loader's order: scale, then rotate_y (0 here), then translate.
  const glm::mat4 transform =
      glm::scale(glm::translate(glm::mat4(1.0f), position), glm::vec3(scale));
  const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
  const std::string stem = std::filesystem::path(path).stem().string();
  for (const ModelPart& part : model.parts) {
    Material material;
    std::string material_name = part.material_name.empty() ? stem : part.material_name;
    for (std::size_t i = 0; i < model.material_names.size(); ++i) {
      if (model.material_names[i] == part.material_name) material = model.materials[i];
    }
    scene->materials.push_back(material);
    scene->material_names.push_back(unique_material_name(*scene, material_name));
    Object object;
    object.name = stem + (part.material_name.empty() ? "" : ":" + part.material_name);
    object.type = ObjectType::mesh;
    object.material = static_cast<int>(scene->materials.size()) - 1;
    object.params.file = absolute;
    object.params.group = part.material_name;
    object.params.position = position;
    object.params.scale = glm::vec3(scale);
    object.params.smooth = true;
    Mesh mesh = part.mesh;
    transform_mesh(mesh, transform);
    object.mesh = std::make_shared<const Mesh>(std::move(mesh));
    scene->objects.push_back(std::move(object));
  }
  const int first_new = static_cast<int>(m_document.scene().objects.size());
  m_document.execute(ReplaceScene{scene, "add " + std::filesystem::path(path).filename().string()});
  m_document.seal();
  m_selection.object = first_new;
  remember_recent(RecentKind::model, path);
  for (const std::string& w : model.warnings) m_commands.info("warning: " + w);
  // glTF materials read as the fitted Phong (or assimp's rule), with both errors.
  for (const std::string& n : model.notes) m_commands.info(n);
  m_commands.info("added " + std::to_string(model.parts.size()) + " object(s) from " + path);
}

void FileActions::save_scene_as(const std::string& requested) {
  const std::string path = requested;  // may refer into the document, which changes below
  Scene scene = m_document.scene();
  move_document(scene, path);
  save_scene(scene, path);
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
  m_selection.object = std::max(0, r.selected_object);
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

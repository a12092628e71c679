#include "io/scene/scene_loader.h"

#include <filesystem>
#include <utility>

#include "base/atomic_file.h"
#include "base/error.h"
#include "base/memory_budget.h"
#include "base/text/ascii.h"
#include "base/text/text_distance.h"
#include "io/image/scene_in_png.h"
#include "io/json/field_json.h"
#include "io/json/json_location.h"
#include "io/json/material_json.h"
#include "io/json/name_escape.h"
#include "io/model/model_map_cache.h"
#include "io/scene/environment_reader.h"
#include "io/scene/material_maps.h"
#include "io/scene/scene_files.h"
#include "io/scene/scene_json_reader.h"
#include "io/scene/scene_object_reader.h"
#include "scene/fields/fields.h"

namespace gloss {

namespace {

Camera read_camera(const JsonObjectReader& top) {
  Camera camera;
  if (!top.has("camera")) return camera;
  const JsonObjectReader reader(top.required("camera"), top.file(), "camera",
                                allowed_keys(camera_fields()));
  read_fields(reader, camera_fields(), camera);
  return camera;
}

std::vector<PointLight> read_lights(const JsonObjectReader& top) {
  std::vector<PointLight> lights;
  if (!top.has("lights")) return lights;
  const nlohmann::json& array = top.required("lights");
  if (!array.is_array()) top.fail("lights", "expected an array of lights");
  for (std::size_t i = 0; i < array.size(); ++i) {
    const JsonObjectReader reader(array[i], top.file(), index_path("lights", i),
                                  allowed_keys(light_fields()));
    PointLight light;
    read_fields(reader, light_fields(), light);
    lights.push_back(light);
  }
  return lights;
}

// The `environment` block: its map read now (relative paths against the scene's folder), the map
// and the engine's tables for it counted against what the budget leaves besides the geometry.
Environment read_environment(const JsonObjectReader& top, const std::string& base_dir,
                             std::uint64_t claimed_bytes, std::vector<std::string>* warnings) {
  Environment environment;
  if (!top.has("environment")) return environment;
  const JsonObjectReader reader(top.required("environment"), top.file(), "environment",
                                allowed_keys(environment_fields(), {"file"}));
  read_fields(reader, environment_fields(), environment);
  environment.file = reader.string("file");
  if (environment.file.empty()) reader.fail("file", "must name a map file");
  const std::filesystem::path file(environment.file);
  const std::string path = file.is_absolute() || base_dir.empty()
                               ? file.string()
                               : (std::filesystem::path(base_dir) / file).string();
  const std::uint64_t budget = memory_budget_bytes();
  if (claimed_bytes >= budget) {
    reader.fail("file", "no memory budget is left for a map after the geometry (" +
                            memory_budget_text() + ")");
  }
  try {
    environment.map = read_environment_map(path, budget - claimed_bytes, warnings);
  } catch (const InputError& error) {
    // One line naming the scene, the field and the map file (error.what() names the file).
    reader.fail("file", error.what());
  }
  return environment;
}

MaterialMap read_materials(const JsonObjectReader& top) {
  MaterialMap materials;
  if (!top.has("materials")) return materials;
  const nlohmann::json& block = top.required("materials");
  if (!block.is_object()) top.fail("materials", "expected an object {name: material, ...}");
  for (const auto& item : block.items()) {
    if (item.key().empty()) top.fail("materials", "a material name must not be empty");
    materials.emplace(
        unescape_name(item.key()),
        material_from_json(item.value(), top.file(), child_path("materials", item.key())));
  }
  return materials;
}

// Sizes are range-checked as they are read, on the JSON number, before anything is allocated.
RenderSettings read_render(const JsonObjectReader& top) {
  RenderSettings render;
  if (!top.has("render")) return render;
  const JsonObjectReader reader(top.required("render"), top.file(), "render",
                                allowed_keys(render_fields()));
  read_fields(reader, render_fields(), render);
  return render;
}

// Objects hold material names until every object (and every OBJ's MTL) has been read; then the
// materials are numbered in name order and each object gets its index.
void resolve_materials(const std::string& file, const MaterialMap& materials,
                       std::vector<PendingObject>& pending, Scene& scene) {
  for (const auto& [name, material] : materials) {
    scene.material_names.push_back(name);
    scene.materials.push_back(material);
  }
  for (PendingObject& item : pending) {
    item.object.material = find_material(scene, item.material_name);
    if (item.object.material < 0) {
      const std::string hint =
          scene.material_names.empty()
              ? std::string(" (the scene defines no materials)")
              : did_you_mean(nearest_words(item.material_name, scene.material_names, 3));
      fail_field(file, item.field, "unknown material '" + item.material_name + "'" + hint);
    }
    scene.objects.push_back(std::move(item.object));
  }
}

// A materials file (material_io.h: only a non-empty "materials" block) opened as a scene would
// fail on its missing "objects"; this says what the file is and where it belongs instead.
constexpr const char* kLoadMaterialsHint =
    "is a materials file, not a scene: load it with File > Load materials in the editor";

void refuse_materials_file(const nlohmann::json& root, const std::string& path) {
  if (root.is_object() && root.size() == 1 && root.contains("materials") &&
      root["materials"].is_object() && !root["materials"].empty()) {
    throw InputError(path, std::string("this ") + kLoadMaterialsHint);
  }
}

bool has_mtl_extension(const std::string& path) {
  return lower_extension(path) == ".mtl";
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& path,
                  std::vector<std::string>* warnings, std::vector<std::string>* notes) {
  const nlohmann::json root = parse_json_text(text, path);
  refuse_materials_file(root, path);
  const JsonObjectReader top(root, path, "",
                             allowed_keys(scene_fields(), {"camera", "lights", "materials",
                                                           "objects", "render", "environment"}));

  Scene scene;
  scene.path = path;
  scene.camera = read_camera(top);
  read_fields(top, scene_fields(), scene);
  scene.lights = read_lights(top);
  scene.render = read_render(top);
  MaterialMap materials = read_materials(top);

  const nlohmann::json& objects = top.required("objects");
  if (!objects.is_array()) top.fail("objects", "expected an array of objects");
  ObjectReadContext context;
  context.file = path;
  context.base_dir = std::filesystem::path(path).parent_path().string();  // "" = current folder
  context.warnings = warnings;
  context.notes = notes;
  std::uint64_t claimed_bytes = 0;
  context.budget_bytes = memory_budget_bytes();
  context.claimed_bytes = &claimed_bytes;
  ModelMapCache model_maps;  // each model loaded once, for its objects and the maps named in it
  context.model_maps = &model_maps;
  std::vector<PendingObject> pending;
  claim_geometry_in_advance(objects, context);
  for (std::size_t i = 0; i < objects.size(); ++i) {
    read_scene_object(objects[i], i, context, materials, pending);
  }
  // The maps the scene's own materials name (a model's came with it), after the geometry.
  MapReadContext maps;
  maps.file = path;
  maps.base_dir = context.base_dir;
  maps.claimed_bytes = &claimed_bytes;
  maps.warnings = warnings;
  maps.model_maps = &model_maps;
  for (auto& [name, material] : materials) {
    read_material_maps(material, child_path("materials", escape_name(name)), maps);
  }
  resolve_materials(path, materials, pending, scene);
  scene.environment = read_environment(top, context.base_dir, claimed_bytes, warnings);
  validate_scene(scene);
  return scene;
}

Scene load_scene(const std::string& path, std::vector<std::string>* warnings,
                 std::vector<std::string>* notes) {
  if (has_png_signature(path)) return load_scene_from_png(path, warnings, notes);
  if (has_mtl_extension(path)) {
    throw InputError(path, std::string("this MTL file ") + kLoadMaterialsHint);
  }
  return parse_scene(read_text_file(path), path, warnings, notes);
}

void save_scene(const Scene& scene, const std::string& path) {
  Scene moved = scene;
  rebase_scene_files(moved, path);  // relative names follow the new folder
  write_text_atomically(path, scene_to_json_text(moved));
}

Scene with_teapot_tessellation(const Scene& scene, int level) {
  nlohmann::json doc = nlohmann::json::parse(scene_to_json_text(scene));
  for (auto& object : doc["objects"]) {
    if (object.value("type", "") == "teapot") object["tessellation"] = level;
  }
  Scene out = parse_scene(doc.dump(), scene.path);
  out.render = scene.render;
  return out;
}

}  // namespace gloss

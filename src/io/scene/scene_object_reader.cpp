#include "io/scene/scene_object_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <new>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "base/error.h"
#include "base/memory_budget.h"
#include "base/text/text_distance.h"
#include "io/json/field_json.h"
#include "io/json/name_escape.h"
#include "io/model/model_loader.h"
#include "io/model/model_map_cache.h"
#include "io/model/model_maps.h"
#include "io/model/teapot_reader.h"
#include "io/scene/scene_json_reader.h"
#include "io/scene/scene_loader.h"
#include "scene/fields/fields.h"
#include "scene/geometry/placement.h"
#include "scene/geometry/shapes.h"
#include "scene/limits.h"
#include "scene/memory/memory_estimate.h"

namespace gloss {

namespace {

const std::vector<std::string> kTypeNames = {"sphere", "quad", "box", "teapot", "mesh"};

// The keys each object type accepts (docs/scene-format.md).
std::vector<std::string> allowed_keys(ObjectType type) {
  switch (type) {
    case ObjectType::sphere:
      return allowed_keys(object_fields(),
                          {"type", "name", "material", "transform", "center", "radius"});
    case ObjectType::quad:
      return allowed_keys(object_fields(), {"type", "name", "material", "transform", "vertices"});
    case ObjectType::box:
      return allowed_keys(object_fields(), {"type", "name", "material", "transform", "min", "max",
                                            "rotate_y", "position"});
    case ObjectType::teapot:
      return allowed_keys(object_fields(), {"type", "name", "material", "transform", "position",
                                            "rotate_y", "scale", "tessellation", "smooth"});
    case ObjectType::mesh:
      return allowed_keys(object_fields(),
                          {"type", "name", "material", "transform", "file", "group", "position",
                           "scale", "rotate_y", "smooth", "crease_angle"});
  }
  return {};
}

// The object's own fields of the table ("hidden") and its "transform" block; the pivot is left
// unset (following the object's centre) unless the file gives it.
void read_placement(const JsonObjectReader& reader, Object& object) {
  read_fields(reader, object_fields(), object);
  if (!reader.has("transform")) return;
  const JsonObjectReader block(reader.required("transform"), reader.file(),
                               reader.path("transform"), allowed_keys(transform_fields()));
  read_fields(block, transform_fields(), object.transform);
}

ObjectType read_type(const nlohmann::json& value, const std::string& file,
                     const std::string& path) {
  if (!value.is_object()) fail_field(file, path, "expected an object");
  const auto it = value.find("type");
  if (it == value.end()) fail_field(file, child_path(path, "type"), "missing required field");
  const std::string name = json_string(*it, file, child_path(path, "type"));
  for (std::size_t i = 0; i < kTypeNames.size(); ++i) {
    if (kTypeNames[i] == name) return static_cast<ObjectType>(i);
  }
  fail_field(
      file, child_path(path, "type"),
      "unknown object type '" + name + "'" + did_you_mean(nearest_words(name, kTypeNames, 1)));
}

// "scale": one number for all axes or [sx, sy, sz]; no axis may be 0 (the mesh would collapse).
glm::vec3 read_scale(const JsonObjectReader& reader) {
  if (!reader.has("scale")) return glm::vec3(1.0f);
  const nlohmann::json& value = reader.required("scale");
  const glm::vec3 scale = value.is_number()
                              ? glm::vec3(json_float(value, reader.file(), reader.path("scale")))
                              : json_vec3(value, reader.file(), reader.path("scale"));
  if (scale.x == 0.0f || scale.y == 0.0f || scale.z == 0.0f) {
    reader.fail("scale", "must not be 0 on any axis");
  }
  return scale;
}

// translate(position) * rotate_y * scale, the placement of teapots and model meshes.
glm::mat4 placement(const ShapeParams& params) {
  glm::mat4 m = glm::translate(glm::mat4(1.0f), params.position);
  m = glm::rotate(m, glm::radians(params.rotate_y), glm::vec3(0.0f, 1.0f, 0.0f));
  return glm::scale(m, params.scale);
}

// Placed vertices within the coordinate limit (scene/limits.h), where float arithmetic on them
// stays finite; a teapot scaled by 1e30 is refused here, naming the object.
void check_placed_bounds(const Mesh& mesh, const ObjectReadContext& context,
                         const std::string& path) {
  glm::vec3 lo, hi;
  if (!mesh_bounds(mesh, lo, hi)) return;
  for (int axis = 0; axis < 3; ++axis) {
    const double reach = std::max(std::fabs(static_cast<double>(lo[axis])),
                                  std::fabs(static_cast<double>(hi[axis])));
    if (!(reach <= kMaxCoordinate)) {
      char text[96];
      std::snprintf(text, sizeof text, "placed vertices reach %g on axis %d, beyond the limit %g",
                    reach, axis, kMaxCoordinate);
      fail_field(context.file, path, text);
    }
  }
}

// Adds an object's triangles to the scene's claim; refuses the object that passes the budget.
// what describes the object for the message ("teapot, tessellation 64").
void claim_geometry(const ObjectReadContext& context, const std::string& path,
                    const std::string& what, std::uint64_t triangles) {
  if (context.claimed_bytes == nullptr) return;
  const std::uint64_t total = *context.claimed_bytes + geometry_bytes(triangles);
  if (total > context.budget_bytes) {
    fail_field(context.file, path,
               what + ", " + std::to_string(triangles) + " triangles: the scene needs ~" +
                   std::to_string(megabytes(total)) + " MB with it, budget " +
                   memory_budget_text());
  }
  *context.claimed_bytes = total;
}

// Drops zero-area triangles; degenerate input is a warning, never an error.
void drop_degenerate(Mesh& mesh, const ObjectReadContext& context, const std::string& path) {
  check_placed_bounds(mesh, context, path);
  const std::size_t dropped = drop_degenerate_triangles(mesh);
  if (dropped > 0 && context.warnings != nullptr) {
    context.warnings->push_back(context.file + ": " + path + ": dropped " +
                                std::to_string(dropped) + " degenerate triangle(s)");
  }
}

// The parts' triangles as one mesh; smooth only when every part carries normals.
Mesh merge_parts(const std::vector<const ModelPart*>& parts) {
  Mesh merged;
  bool smooth = true;
  for (const ModelPart* part : parts) smooth = smooth && part->mesh.smooth();
  for (const ModelPart* part : parts) {
    const auto base = static_cast<unsigned>(merged.positions.size());
    merged.positions.insert(merged.positions.end(), part->mesh.positions.begin(),
                            part->mesh.positions.end());
    if (smooth) {
      merged.normals.insert(merged.normals.end(), part->mesh.normals.begin(),
                            part->mesh.normals.end());
    }
    for (const glm::uvec3& t : part->mesh.triangles) merged.triangles.push_back(t + base);
  }
  return merged;
}

void read_mesh(const JsonObjectReader& reader, const ObjectReadContext& context, Object prototype,
               const std::string& explicit_material, MaterialMap& materials,
               std::vector<PendingObject>& out) {
  ShapeParams& params = prototype.params;
  const std::string material_field = reader.path("material");
  const std::filesystem::path file_path(params.file);
  const std::string resolved = file_path.is_absolute() || context.base_dir.empty()
                                   ? params.file
                                   : (std::filesystem::path(context.base_dir) / file_path).string();
  Model model;
  try {
    ModelOptions options;
    options.smooth = params.smooth;
    options.crease_angle = params.crease_angle;
    if (context.claimed_bytes != nullptr && context.budget_bytes != UINT64_MAX) {
      options.map_budget_bytes = context.budget_bytes > *context.claimed_bytes
                                     ? context.budget_bytes - *context.claimed_bytes
                                     : 1;
    }
    model = load_model(resolved, options);
  } catch (const InputError& error) {
    fail_field(context.file, reader.path("file"), error.what());
  } catch (const std::bad_alloc&) {
    throw;  // not the file's fault as such: exit 1
  } catch (const std::exception& error) {
    // Whatever the model library throws (std::out_of_range, std::length_error ...) is still the
    // file's fault: bad input naming it.
    fail_field(context.file, reader.path("file"), resolved + ": " + error.what());
  }
  for (const std::string& warning : model.warnings) {
    if (context.warnings)
      context.warnings->push_back(context.file + ": " + reader.path("file") + ": " + warning);
  }
  for (const std::string& note : model.notes) {
    if (context.notes)
      context.notes->push_back(context.file + ": " + reader.path("file") + ": " + note);
  }
  if (context.claimed_bytes != nullptr) *context.claimed_bytes += model.map_bytes;
  if (context.model_maps != nullptr) context.model_maps->keep(resolved, model);
  // The model's maps named as the scene names files: relative to the scene's folder.
  name_maps_for_scene(model.materials, params.file);

  std::vector<const ModelPart*> parts;
  std::vector<std::string> groups;
  for (const ModelPart& part : model.parts) {
    groups.push_back(part.material_name);
    if (!reader.has("group") || part.material_name == params.group) parts.push_back(&part);
  }
  if (parts.empty()) {
    reader.fail("group", "no part with material '" + params.group + "' in " + params.file +
                             did_you_mean(nearest_words(params.group, groups, 3)));
  }

  const glm::mat4 transform = placement(params);
  std::uint64_t triangles = 0;
  for (const ModelPart* part : parts) triangles += part->mesh.triangles.size();
  // The file is read by now (its size bounds what that took); its copies are not made yet.
  claim_geometry(context, reader.path(), "mesh " + params.file, triangles);
  auto emit = [&](Mesh mesh, Object object, std::string material_name) {
    transform_mesh(mesh, transform);
    drop_degenerate(mesh, context, reader.path());
    object.shape = std::make_shared<const Mesh>(std::move(mesh));
    place_object(object);
    out.push_back({std::move(object), std::move(material_name), material_field});
  };

  if (!explicit_material.empty()) {
    emit(merge_parts(parts), prototype, explicit_material);
    return;
  }
  // No scene material: one object per part, each with its MTL material. A scene material that
  // already has the name (for example from a saved copy of this scene) takes precedence.
  const std::string stem = file_path.stem().string();
  for (const ModelPart* part : parts) {
    Object object = prototype;
    object.params.group = part->material_name;
    if (parts.size() > 1) object.name += "/" + part->material_name;
    std::string material_name = kDefaultMaterialName;
    for (std::size_t m = 0; m < model.material_names.size(); ++m) {
      if (model.material_names[m] != part->material_name || part->material_name.empty()) continue;
      material_name = stem + "/" + part->material_name;
      materials.emplace(material_name, model.materials[m]);
    }
    if (material_name == kDefaultMaterialName) materials.emplace(material_name, Material{});
    emit(part->mesh, std::move(object), material_name);
  }
}

}  // namespace

void claim_geometry_in_advance(const nlohmann::json& objects, const ObjectReadContext& context) {
  if (!objects.is_array() || context.claimed_bytes == nullptr) return;
  const std::uint64_t start = *context.claimed_bytes;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const nlohmann::json& value = objects[i];
    if (!value.is_object() || value.value("type", nlohmann::json()) != "teapot") continue;
    const auto level = value.find("tessellation");
    long long tessellation = 8;
    if (level != value.end()) {
      if (!level->is_number_integer() || *level < 1 || *level > 64) continue;
      tessellation = level->get<long long>();
    }
    claim_geometry(context, index_path("objects", i),
                   "teapot, tessellation " + std::to_string(tessellation),
                   teapot_triangles(static_cast<int>(tessellation)));
  }
  *context.claimed_bytes = start;  // the reading pass claims each object again as it reads it
}

void read_scene_object(const nlohmann::json& value, std::size_t index,
                       const ObjectReadContext& context, MaterialMap& materials,
                       std::vector<PendingObject>& out) {
  const std::string path = index_path("objects", index);
  const ObjectType type = read_type(value, context.file, path);
  const JsonObjectReader reader(value, context.file, path, allowed_keys(type));

  Object object;
  object.type = type;
  // Names and paths are bytes, escaped where they are not UTF-8 (io/json/name_escape.h).
  object.name = unescape_name(reader.string("name", to_string(type) + std::to_string(index)));
  const std::string material = unescape_name(
      type == ObjectType::mesh ? reader.string("material", "") : reader.string("material"));
  if (reader.has("material") && material.empty()) reader.fail("material", "must not be empty");
  ShapeParams& params = object.params;
  read_placement(reader, object);
  Mesh mesh;

  switch (type) {
    case ObjectType::sphere:
      params.center = reader.vec3("center");
      params.radius = reader.number("radius");
      if (!(params.radius > 0.0f)) reader.fail("radius", "must be greater than 0");
      place_object(object);
      out.push_back({std::move(object), material, reader.path("material")});
      return;
    case ObjectType::quad: {
      const nlohmann::json& vertices = reader.required("vertices");
      if (!vertices.is_array() || vertices.size() != 4) {
        reader.fail("vertices", "expected an array of 4 corners [x, y, z]");
      }
      for (std::size_t i = 0; i < 4; ++i) {
        params.quad[i] =
            json_vec3(vertices[i], context.file, index_path(reader.path("vertices"), i));
      }
      mesh = make_quad(params.quad[0], params.quad[1], params.quad[2], params.quad[3]);
      break;
    }
    case ObjectType::box: {
      params.box_min = reader.vec3("min");
      params.box_max = reader.vec3("max");
      for (int axis = 0; axis < 3; ++axis) {
        if (!(params.box_min[axis] < params.box_max[axis])) {
          reader.fail("max", "must be greater than min on every axis");
        }
      }
      params.rotate_y = reader.number("rotate_y", params.rotate_y);
      params.position = reader.vec3("position", params.position);
      // Rotation about the vertical axis through the box's centre, then the translation.
      const glm::vec3 centre = 0.5f * (params.box_min + params.box_max);
      glm::mat4 m = glm::translate(glm::mat4(1.0f), params.position + centre);
      m = glm::rotate(m, glm::radians(params.rotate_y), glm::vec3(0.0f, 1.0f, 0.0f));
      m = glm::translate(m, -centre);
      mesh = make_box(params.box_min, params.box_max);
      transform_mesh(mesh, m);
      break;
    }
    case ObjectType::teapot:
      params.position = reader.vec3("position", params.position);
      params.rotate_y = reader.number("rotate_y", params.rotate_y);
      params.scale = read_scale(reader);
      params.tessellation = static_cast<int>(reader.integer("tessellation", 8, 1, 64));
      params.smooth = reader.boolean("smooth", params.smooth);
      // Counted before tessellating: 1000 teapots at 64 would otherwise allocate until bad_alloc.
      claim_geometry(context, path, "teapot, tessellation " + std::to_string(params.tessellation),
                     teapot_triangles(params.tessellation));
      mesh = tessellate_patches(teapot_patches(), params.tessellation, params.smooth);
      transform_mesh(mesh, placement(params));
      break;
    case ObjectType::mesh:
      params.file = unescape_name(reader.string("file"));
      if (params.file.empty()) reader.fail("file", "must not be empty");
      params.group = unescape_name(reader.string("group", ""));
      params.position = reader.vec3("position", params.position);
      params.rotate_y = reader.number("rotate_y", params.rotate_y);
      params.scale = read_scale(reader);
      params.smooth = reader.boolean("smooth", params.smooth);
      params.crease_angle = reader.number("crease_angle", params.crease_angle);
      if (!(params.crease_angle >= 0.0f && params.crease_angle <= 180.0f)) {
        reader.fail("crease_angle", "must be 0..180 degrees");
      }
      read_mesh(reader, context, std::move(object), material, materials, out);
      return;
  }
  drop_degenerate(mesh, context, path);
  if (type != ObjectType::teapot)
    claim_geometry(context, path, to_string(type), mesh.triangles.size());
  object.shape = std::make_shared<const Mesh>(std::move(mesh));
  place_object(object);
  out.push_back({std::move(object), material, reader.path("material")});
}

Mesh teapot_mesh(const ShapeParams& params) {
  Mesh mesh = tessellate_patches(teapot_patches(), params.tessellation, params.smooth);
  transform_mesh(mesh, placement(params));
  drop_degenerate_triangles(mesh);
  return mesh;
}

}  // namespace gloss

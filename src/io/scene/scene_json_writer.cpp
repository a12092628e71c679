// scene_to_json_text of scene_loader.h: a Scene back to the file format of docs/scene-format.md,
// laid out for people (short values on one line, keys in a fixed reading order) and exact: every
// float is written with the fewest digits that read back to the same float.
#include "io/scene/scene_loader.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/json/field_json.h"
#include "io/json/material_json.h"
#include "io/json/name_escape.h"
#include "scene/fields/fields.h"

namespace gloss {

namespace {

// Insertion order is reading order: the tables' order for fields, a fixed one for objects.
using Json = nlohmann::ordered_json;

constexpr std::size_t kLineWidth = 100;

// One line: {"a": 1, "b": [0, 1, 2]}.
std::string compact(const Json& value) {
  if (value.is_array()) {
    std::string out = "[";
    for (std::size_t i = 0; i < value.size(); ++i) out += (i ? ", " : "") + compact(value[i]);
    return out + "]";
  }
  if (value.is_object()) {
    std::string out = "{";
    bool first = true;
    for (const auto& item : value.items()) {
      out += (first ? "" : ", ") + Json(item.key()).dump() + ": " + compact(item.value());
      first = false;
    }
    return out + "}";
  }
  return value.dump();
}

// The root and anything that does not fit on its line are spread one member per line.
void pretty(const Json& value, std::size_t indent, std::size_t used, bool force_open,
            std::string& out) {
  const std::string one_line = compact(value);
  const bool container = value.is_array() || value.is_object();
  if (!container || value.empty() || (!force_open && used + one_line.size() <= kLineWidth)) {
    out += one_line;
    return;
  }
  const std::string pad(indent + 2, ' ');
  out += value.is_array() ? "[\n" : "{\n";
  if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) {
      out += pad;
      pretty(value[i], indent + 2, pad.size() + 1, false, out);
      out += i + 1 < value.size() ? ",\n" : "\n";
    }
  } else {
    std::size_t i = 0;
    for (const auto& item : value.items()) {
      const std::string head = Json(item.key()).dump() + ": ";
      out += pad + head;
      pretty(item.value(), indent + 2, pad.size() + head.size() + 1, false, out);
      out += ++i < value.size() ? ",\n" : "\n";
    }
  }
  out += std::string(indent, ' ') + (value.is_array() ? "]" : "}");
}

Json vec3_json(const glm::vec3& v) {
  return Json::array({float_json(v.x), float_json(v.y), float_json(v.z)});
}

// Keys in reading order: what it is, where its data comes from, its shape and placement, then
// the material it uses.
Json object_json(const Object& object, const std::string& material_name) {
  const ShapeParams& p = object.params;
  const ShapeParams defaults;
  const bool placed = object.type == ObjectType::box || object.type == ObjectType::teapot ||
                      object.type == ObjectType::mesh;
  const bool scaled = object.type == ObjectType::teapot || object.type == ObjectType::mesh;
  Json j;
  j["type"] = to_string(object.type);
  j["name"] = escape_name(object.name);
  if (object.type == ObjectType::mesh) {
    j["file"] = escape_name(p.file);
    if (!p.group.empty()) j["group"] = escape_name(p.group);
  }
  // Optional placement fields are written only when they differ from their defaults.
  if (placed && p.position != defaults.position) j["position"] = vec3_json(p.position);
  if (object.type == ObjectType::sphere) {
    j["center"] = vec3_json(p.center);
    j["radius"] = float_json(p.radius);
  }
  if (object.type == ObjectType::quad) {
    j["vertices"] = Json::array();
    for (const glm::vec3& corner : p.quad) j["vertices"].push_back(vec3_json(corner));
  }
  if (object.type == ObjectType::box) {
    j["min"] = vec3_json(p.box_min);
    j["max"] = vec3_json(p.box_max);
  }
  if (placed && p.rotate_y != defaults.rotate_y) j["rotate_y"] = float_json(p.rotate_y);
  if (scaled && p.scale != defaults.scale) {
    j["scale"] = p.scale.x == p.scale.y && p.scale.y == p.scale.z ? Json(float_json(p.scale.x))
                                                                  : vec3_json(p.scale);
  }
  if (object.type == ObjectType::teapot && p.tessellation != defaults.tessellation) {
    j["tessellation"] = p.tessellation;
  }
  if (scaled && p.smooth != defaults.smooth) j["smooth"] = p.smooth;
  if (object.type == ObjectType::mesh && p.crease_angle != defaults.crease_angle) {
    j["crease_angle"] = float_json(p.crease_angle);
  }
  // The transform's fields that are not the identity's; the pivot only when it was given.
  Json transform = Json::object();
  ObjectTransform identity;
  identity.pivot = object.transform.pivot_set ? glm::vec3(NAN) : object.transform.pivot;
  write_changed_fields(transform_fields(), object.transform, identity, transform);
  if (!transform.empty()) j["transform"] = transform;
  write_changed_fields(object_fields(), object, Object{}, j);
  j["material"] = escape_name(material_name);
  return j;
}

}  // namespace

std::string scene_to_json_text(const Scene& scene) {
  Json root;
  write_fields(camera_fields(), scene.camera, root["camera"]);
  write_fields(scene_fields(), scene, root);
  root["lights"] = Json::array();
  for (const PointLight& light : scene.lights) {
    Json j;
    write_fields(light_fields(), light, j);
    root["lights"].push_back(j);
  }
  // Materials by name, as the loader numbers them.
  std::vector<std::size_t> order(scene.materials.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return scene.material_names.at(a) < scene.material_names.at(b);
  });
  root["materials"] = Json::object();
  for (std::size_t i : order) {
    root["materials"][escape_name(scene.material_names[i])] = material_to_json(scene.materials[i]);
  }
  root["objects"] = Json::array();
  for (const Object& object : scene.objects) {
    const bool known =
        object.material >= 0 && object.material < static_cast<int>(scene.material_names.size());
    root["objects"].push_back(
        object_json(object, known ? scene.material_names[object.material] : std::string()));
  }
  if (!scene.environment.file.empty()) {
    Json& environment = root["environment"];
    environment["file"] = scene.environment.file;
    write_fields(environment_fields(), scene.environment, environment);
  }
  write_fields(render_fields(), scene.render, root["render"]);
  std::string out;
  pretty(root, 0, 0, true, out);
  return out + "\n";
}

}  // namespace gloss

// scene_to_json_text of scene_loader.h: a Scene back to the file format of docs/scene-format.md,
// laid out for people (short values on one line, keys in a fixed reading order) and exact: every
// float is written with the fewest digits that read back to the same float.
#include "io/scene_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/material_json.h"

namespace gloss {

namespace {

// Reading order of keys; keys not listed (material names) follow in alphabetical order.
const std::vector<std::string> kKeyOrder = {"type",        "name",
                                            "preset",      "file",
                                            "group",       "camera",
                                            "eye",         "target",
                                            "up",          "fov_y",
                                            "background",  "position",
                                            "center",      "radius",
                                            "vertices",    "min",
                                            "max",         "rotate_y",
                                            "scale",       "tessellation",
                                            "smooth",      "ambient",
                                            "diffuse",     "specular",
                                            "emission",    "shininess",
                                            "attenuation", "lights",
                                            "materials",   "material",
                                            "objects",     "render",
                                            "width",       "height",
                                            "spp",         "model",
                                            "shadows",     "energy_normalize",
                                            "srgb",        "seed",
                                            "pow"};

constexpr std::size_t kLineWidth = 100;

std::size_t key_rank(const std::string& key) {
  for (std::size_t i = 0; i < kKeyOrder.size(); ++i) {
    if (kKeyOrder[i] == key) return i;
  }
  return kKeyOrder.size();
}

std::vector<std::string> ordered_keys(const nlohmann::json& object) {
  std::vector<std::string> keys;
  for (const auto& item : object.items()) keys.push_back(item.key());  // alphabetical already
  std::stable_sort(keys.begin(), keys.end(), [](const std::string& a, const std::string& b) {
    return key_rank(a) < key_rank(b);
  });
  return keys;
}

// One line: {"a": 1, "b": [0, 1, 2]}.
std::string compact(const nlohmann::json& value) {
  if (value.is_array()) {
    std::string out = "[";
    for (std::size_t i = 0; i < value.size(); ++i) out += (i ? ", " : "") + compact(value[i]);
    return out + "]";
  }
  if (value.is_object()) {
    std::string out = "{";
    bool first = true;
    for (const std::string& key : ordered_keys(value)) {
      out += (first ? "" : ", ") + nlohmann::json(key).dump() + ": " + compact(value.at(key));
      first = false;
    }
    return out + "}";
  }
  return value.dump();
}

// The root and anything that does not fit on its line are spread one member per line.
void pretty(const nlohmann::json& value, std::size_t indent, std::size_t used, bool force_open,
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
    const std::vector<std::string> keys = ordered_keys(value);
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const std::string head = nlohmann::json(keys[i]).dump() + ": ";
      out += pad + head;
      pretty(value.at(keys[i]), indent + 2, pad.size() + head.size() + 1, false, out);
      out += i + 1 < keys.size() ? ",\n" : "\n";
    }
  }
  out += std::string(indent, ' ') + (value.is_array() ? "]" : "}");
}

// The shortest decimal (6 to 9 significant digits) that the loader's double-to-float conversion
// turns back into exactly f; whole numbers are written as integers.
nlohmann::json float_json(float f) {
  for (int digits = 6; digits <= 9; ++digits) {
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, static_cast<double>(f));
    const double d = std::strtod(text, nullptr);
    if (static_cast<float>(d) != f) continue;
    if (d == std::floor(d) && std::fabs(d) < 1e15) return static_cast<long long>(d);
    return d;
  }
  return static_cast<double>(f);
}

nlohmann::json vec3_json(const glm::vec3& v) {
  return nlohmann::json::array({float_json(v.x), float_json(v.y), float_json(v.z)});
}

// Floats inside material_to_json's output are re-written exactly (it may hold float-as-double).
nlohmann::json exact_floats(const nlohmann::json& value) {
  if (value.is_number_float()) return float_json(static_cast<float>(value.get<double>()));
  if (!value.is_structured()) return value;
  nlohmann::json out = value;
  for (auto& item : out.items()) item.value() = exact_floats(item.value());
  return out;
}

nlohmann::json object_json(const Object& object, const std::string& material_name) {
  const ShapeParams& p = object.params;
  const ShapeParams defaults;
  nlohmann::json j;
  j["type"] = to_string(object.type);
  j["name"] = object.name;
  j["material"] = material_name;
  // Optional placement fields are written only when they differ from their defaults.
  auto placement = [&](bool with_scale) {
    if (p.position != defaults.position) j["position"] = vec3_json(p.position);
    if (p.rotate_y != defaults.rotate_y) j["rotate_y"] = float_json(p.rotate_y);
    if (with_scale && p.scale != defaults.scale) {
      j["scale"] = p.scale.x == p.scale.y && p.scale.y == p.scale.z ? float_json(p.scale.x)
                                                                    : vec3_json(p.scale);
    }
  };
  switch (object.type) {
    case ObjectType::sphere:
      j["center"] = vec3_json(object.center);
      j["radius"] = float_json(object.radius);
      break;
    case ObjectType::quad:
      j["vertices"] = nlohmann::json::array();
      for (const glm::vec3& corner : p.quad) j["vertices"].push_back(vec3_json(corner));
      break;
    case ObjectType::box:
      j["min"] = vec3_json(p.box_min);
      j["max"] = vec3_json(p.box_max);
      placement(false);
      break;
    case ObjectType::teapot:
      placement(true);
      if (p.tessellation != defaults.tessellation) j["tessellation"] = p.tessellation;
      if (p.smooth != defaults.smooth) j["smooth"] = p.smooth;
      break;
    case ObjectType::mesh:
      j["file"] = p.file;
      if (!p.group.empty()) j["group"] = p.group;
      placement(true);
      if (p.smooth != defaults.smooth) j["smooth"] = p.smooth;
      break;
  }
  return j;
}

nlohmann::json light_json(const PointLight& light) {
  return {{"position", vec3_json(light.position)},
          {"ambient", vec3_json(light.ambient)},
          {"diffuse", vec3_json(light.diffuse)},
          {"specular", vec3_json(light.specular)},
          {"attenuation", vec3_json(light.attenuation)}};
}

nlohmann::json render_json(const RenderSettings& r) {
  return {{"width", r.width},
          {"height", r.height},
          {"spp", r.spp},
          {"model", to_string(r.model)},
          {"shadows", r.shadows},
          {"energy_normalize", r.energy_normalize},
          {"srgb", r.srgb},
          {"seed", r.seed},
          {"pow", r.pow == PowMode::exact ? "exact" : "fast"}};
}

}  // namespace

std::string scene_to_json_text(const Scene& scene) {
  nlohmann::json root;
  root["camera"] = {{"eye", vec3_json(scene.camera.eye)},
                    {"target", vec3_json(scene.camera.target)},
                    {"up", vec3_json(scene.camera.up)},
                    {"fov_y", float_json(scene.camera.fov_y)}};
  root["background"] = vec3_json(scene.background);
  root["ambient"] = vec3_json(scene.ambient);
  root["lights"] = nlohmann::json::array();
  for (const PointLight& light : scene.lights) root["lights"].push_back(light_json(light));
  root["materials"] = nlohmann::json::object();
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    root["materials"][scene.material_names.at(i)] =
        exact_floats(material_to_json(scene.materials[i]));
  }
  root["objects"] = nlohmann::json::array();
  for (const Object& object : scene.objects) {
    const bool known =
        object.material >= 0 && object.material < static_cast<int>(scene.material_names.size());
    root["objects"].push_back(
        object_json(object, known ? scene.material_names[object.material] : std::string()));
  }
  root["render"] = render_json(scene.render);
  std::string out;
  pretty(root, 0, 0, true, out);
  return out + "\n";
}

}  // namespace gloss

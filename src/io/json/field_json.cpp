#include "io/json/field_json.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "base/error.h"
#include "base/field_path.h"
#include "base/text/text_distance.h"

namespace gloss {

std::string float_text(float f) {
  char text[40] = {};
  for (int digits = 6; digits <= 9; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, static_cast<double>(f));
    if (static_cast<float>(std::strtod(text, nullptr)) == f) break;
  }
  return text;
}

namespace {

const std::vector<std::string> kMapKeys = {"file", "wrap", "offset", "scale", "rotation", "uv_set"};
const std::vector<std::string> kWrapNames = {"repeat", "clamp", "mirror"};

Wrap read_wrap(const nlohmann::json& value, const std::string& file, const std::string& field) {
  const std::string name = json_string(value, file, field);
  for (std::size_t i = 0; i < kWrapNames.size(); ++i) {
    if (kWrapNames[i] == name) return static_cast<Wrap>(i);
  }
  fail_field(file, field,
             "unknown wrap '" + name + "'" + did_you_mean(nearest_words(name, kWrapNames, 1)) +
                 " (repeat, clamp or mirror)");
}

// [a, b], or one number for both.
glm::vec2 read_pair(const nlohmann::json& value, const std::string& file,
                    const std::string& field) {
  if (value.is_number()) return glm::vec2(json_float(value, file, field));
  if (!value.is_array() || value.size() != 2) fail_field(file, field, "expected [u, v]");
  return {json_float(value[0], file, index_path(field, 0)),
          json_float(value[1], file, index_path(field, 1))};
}

// A map field: a path, or {"file": ..., "wrap": ..., "offset": ..., "scale": ..., "rotation":
// ..., "uv_set": ...} (docs/scene-format.md, "Maps"). The image is read later, against the
// scene's folder (io/scene/material_maps.h).
TextureMap read_map(const JsonObjectReader& reader, const std::string& key) {
  TextureMap map;
  const nlohmann::json& value = reader.required(key);
  if (value.is_string()) {
    map.file = json_string(value, reader.file(), reader.path(key));
    if (map.file.empty()) reader.fail(key, "must name an image file");
    return map;
  }
  if (!value.is_object()) reader.fail(key, "expected a file path or a map object {\"file\": ...}");
  const JsonObjectReader object(value, reader.file(), reader.path(key), kMapKeys);
  map.file = object.string("file");
  if (map.file.empty()) object.fail("file", "must name an image file");
  if (object.has("wrap")) {
    const nlohmann::json& wrap = object.required("wrap");
    if (wrap.is_array()) {
      if (wrap.size() != 2) object.fail("wrap", "expected a mode or [u mode, v mode]");
      map.wrap = {read_wrap(wrap[0], object.file(), index_path(object.path("wrap"), 0)),
                  read_wrap(wrap[1], object.file(), index_path(object.path("wrap"), 1))};
    } else {
      map.wrap[0] = map.wrap[1] = read_wrap(wrap, object.file(), object.path("wrap"));
    }
  }
  if (object.has("offset")) {
    map.offset = read_pair(object.required("offset"), object.file(), object.path("offset"));
  }
  if (object.has("scale")) {
    map.scale = read_pair(object.required("scale"), object.file(), object.path("scale"));
  }
  map.rotation = object.number("rotation", 0.0f);
  map.uv_set = static_cast<int>(object.integer("uv_set", 0, 0, 1));
  return map;
}

nlohmann::json pair_json(const glm::vec2& v) {
  return nlohmann::json::array({float_json(v.x), float_json(v.y)});
}

nlohmann::json map_json(const TextureMap& map) {
  if (plain_settings(map)) return map.file;
  const TextureMap defaults;
  nlohmann::ordered_json out;
  out["file"] = map.file;
  if (map.wrap != defaults.wrap) {
    out["wrap"] =
        map.wrap[0] == map.wrap[1]
            ? nlohmann::ordered_json(to_string(map.wrap[0]))
            : nlohmann::ordered_json::array({to_string(map.wrap[0]), to_string(map.wrap[1])});
  }
  if (map.offset != defaults.offset) out["offset"] = pair_json(map.offset);
  if (map.scale != defaults.scale) out["scale"] = pair_json(map.scale);
  if (map.rotation != defaults.rotation) out["rotation"] = float_json(map.rotation);
  if (map.uv_set != defaults.uv_set) out["uv_set"] = map.uv_set;
  return out;
}

}  // namespace

nlohmann::json float_json(float f) {
  const std::string text = float_text(f);
  const double d = std::strtod(text.c_str(), nullptr);
  if (d == std::floor(d) && std::fabs(d) < 1e15) return static_cast<long long>(d);
  return d;
}

FieldValue read_field_value(const JsonObjectReader& reader, const std::string& key,
                            const std::string& label, FieldKind kind, double min, double max,
                            const std::vector<const char*>& choices) {
  FieldValue value;
  switch (kind) {
    case FieldKind::colour:
      value.v = reader.vec3(key) + glm::vec3(0.0f);  // + 0 turns -0 into +0
      break;
    case FieldKind::vector:
      value.v = reader.vec3(key);
      break;
    case FieldKind::number:
      value.x = reader.number(key);
      break;
    case FieldKind::whole:
      value.x = static_cast<double>(
          reader.integer(key, 0, static_cast<long long>(min), static_cast<long long>(max)));
      break;
    case FieldKind::flag:
      value.x = reader.boolean(key, false) ? 1.0 : 0.0;
      break;
    case FieldKind::map:
      value.map = read_map(reader, key);
      break;
    case FieldKind::choice: {
      const std::string name = reader.string(key);
      std::vector<std::string> names(choices.begin(), choices.end());
      for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i] == name) {
          value.x = static_cast<double>(i);
          return value;
        }
      }
      reader.fail(key, "unknown " + label + " '" + name + "'" +
                           did_you_mean(nearest_words(name, names, 1)));
    }
  }
  return value;
}

nlohmann::json field_value_json(FieldKind kind, const std::vector<const char*>& choices,
                                const FieldValue& value) {
  switch (kind) {
    case FieldKind::colour:
    case FieldKind::vector:
      return nlohmann::json::array(
          {float_json(value.v.x), float_json(value.v.y), float_json(value.v.z)});
    case FieldKind::number:
      return float_json(static_cast<float>(value.x));
    case FieldKind::whole:
      return static_cast<long long>(value.x);
    case FieldKind::flag:
      return value.x != 0.0;
    case FieldKind::map:
      return map_json(value.map);
    case FieldKind::choice:
      return choices.at(static_cast<std::size_t>(value.x));
  }
  return nullptr;
}

}  // namespace gloss

#include "io/material_io.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"
#include "base/error.h"
#include "base/text_distance.h"
#include "io/json_location.h"
#include "io/material_json.h"
#include "io/preset_table.h"

namespace gloss {

namespace {

const std::vector<std::string> material_keys = {"preset",   "ambient",  "diffuse",
                                                "specular", "emission", "shininess"};

// ---- numbers as text -------------------------------------------------------------------------

// The shortest decimal (at most 9 significant digits, enough for any float) that reads back as
// exactly value, so files stay readable ("0.75164", not "0.7516400218009949") and round trips are
// exact. Assumes the C numeric locale ('.' as decimal point).
std::string float_text(float value) {
  char buffer[32] = {};
  for (int digits = 6; digits <= 9; ++digits) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, static_cast<double>(value));
    if (std::strtof(buffer, nullptr) == value) break;
  }
  return buffer;
}

// The double nearest float_text(value): nlohmann prints it as that same short text.
double json_number(float value) {
  return std::strtod(float_text(value).c_str(), nullptr);
}

// value as a float if it is finite and fits; the double -> float conversion of an out-of-range
// value is undefined, hence the range test first.
bool to_finite_float(double value, float& out) {
  if (!std::isfinite(value) || std::fabs(value) > std::numeric_limits<float>::max()) return false;
  out = static_cast<float>(value) + 0.0f;  // + 0 turns -0 into +0
  return true;
}

// ---- JSON ------------------------------------------------------------------------------------

template <class Json>
Json colour_json(const glm::vec3& colour) {
  return Json::array({json_number(colour.x), json_number(colour.y), json_number(colour.z)});
}

template <class Json>
Json material_json(const Material& material) {
  Json value = Json::object();
  if (!material.preset.empty()) value["preset"] = material.preset;
  value["ambient"] = colour_json<Json>(material.ambient);
  value["diffuse"] = colour_json<Json>(material.diffuse);
  value["specular"] = colour_json<Json>(material.specular);
  value["emission"] = colour_json<Json>(material.emission);
  value["shininess"] = json_number(material.shininess);
  return value;
}

std::string child_field(const std::string& field, const std::string& key) {
  return field.empty() ? key : field + "." + key;
}

[[noreturn]] void fail_field(const std::string& file, const std::string& field,
                             const std::string& message) {
  throw InputError(file, message, 0, 0, field);
}

std::string unknown_key_message(const std::string& key, const std::vector<std::string>& known) {
  return "unknown key '" + key + "' (did you mean '" + nearest_words(key, known, 1).front() + "'?)";
}

float number_from_json(const nlohmann::json& value, const std::string& file,
                       const std::string& field) {
  if (!value.is_number())
    fail_field(file, field, std::string("expected a number, got ") + value.type_name());
  float number = 0;
  if (!to_finite_float(value.get<double>(), number)) {
    fail_field(file, field, "expected a finite number, got " + value.dump());
  }
  if (number < 0) fail_field(file, field, "must be non-negative, got " + value.dump());
  return number;
}

glm::vec3 colour_from_json(const nlohmann::json& value, const std::string& file,
                           const std::string& field) {
  if (!value.is_array()) {
    fail_field(file, field,
               std::string("expected an array of 3 numbers, got ") + value.type_name());
  }
  if (value.size() != 3) {
    fail_field(file, field, "expected 3 numbers, got " + std::to_string(value.size()));
  }
  glm::vec3 colour;
  for (int i = 0; i < 3; ++i) {
    colour[i] = number_from_json(value[i], file, field + "[" + std::to_string(i) + "]");
  }
  return colour;
}

std::string join(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& word : words) out += (out.empty() ? "" : ", ") + word;
  return out;
}

// ---- MTL -------------------------------------------------------------------------------------

// A whitespace-separated token and its 1-based column, for error positions.
struct Token {
  std::string text;
  int column = 1;
};

std::vector<Token> tokenize(const std::string& line) {
  std::vector<Token> tokens;
  std::size_t pos = 0;
  while (true) {
    pos = line.find_first_not_of(" \t", pos);
    if (pos == std::string::npos) return tokens;
    const std::size_t end = std::min(line.find_first_of(" \t", pos), line.size());
    tokens.push_back({line.substr(pos, end - pos), static_cast<int>(pos) + 1});
    pos = end;
  }
}

std::string trim(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

std::string lowercase(std::string text) {
  for (char& c : text) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return text;
}

float mtl_number(const Token& token, const std::string& path, int line) {
  char* end = nullptr;
  const double value = std::strtod(token.text.c_str(), &end);
  float number = 0;
  if (*end != '\0' || !to_finite_float(value, number) || number < 0) {
    throw InputError(path, "expected a non-negative number, got '" + token.text + "'", line,
                     token.column);
  }
  return number;
}

// "Ka r g b" or the single-value shorthand "Ka r" (r = g = b). tokens[0] is the keyword.
glm::vec3 mtl_colour(const std::vector<Token>& tokens, const std::string& path, int line) {
  const std::string& keyword = tokens[0].text;
  if (tokens.size() > 1 &&
      (lowercase(tokens[1].text) == "spectral" || lowercase(tokens[1].text) == "xyz")) {
    throw InputError(
        path,
        "'" + keyword + " " + tokens[1].text + "' is not supported (use " + keyword + " r g b)",
        line, tokens[1].column);
  }
  if (tokens.size() != 2 && tokens.size() != 4) {
    throw InputError(
        path, "'" + keyword + "' expects 3 numbers, got " + std::to_string(tokens.size() - 1), line,
        tokens[0].column);
  }
  if (tokens.size() == 2) return glm::vec3(mtl_number(tokens[1], path, line));
  return glm::vec3(mtl_number(tokens[1], path, line), mtl_number(tokens[2], path, line),
                   mtl_number(tokens[3], path, line));
}

// Names must survive a write and a read: newmtl takes the rest of the line, trimmed.
void check_names(const std::string& path, const std::vector<NamedMaterial>& materials) {
  for (std::size_t i = 0; i < materials.size(); ++i) {
    const std::string& name = materials[i].first;
    if (name.empty() || trim(name) != name || name.find_first_of("\r\n") != std::string::npos) {
      throw RuntimeFailure("cannot write " + path + ": invalid material name '" + name + "'");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (materials[j].first == name) {
        throw RuntimeFailure("cannot write " + path + ": duplicate material name '" + name + "'");
      }
    }
  }
}

}  // namespace

nlohmann::json material_to_json(const Material& material) {
  return material_json<nlohmann::json>(material);
}

Material material_from_json(const nlohmann::json& value, const std::string& file,
                            const std::string& field) {
  if (!value.is_object()) {
    fail_field(file, field, std::string("expected an object, got ") + value.type_name());
  }
  for (const auto& item : value.items()) {
    const std::string& key = item.key();
    bool known = false;
    for (const std::string& candidate : material_keys) known = known || candidate == key;
    if (!known) fail_field(file, child_field(field, key), unknown_key_message(key, material_keys));
  }

  Material material;
  if (value.contains("preset")) {
    const nlohmann::json& preset_value = value["preset"];
    const std::string preset_field = child_field(field, "preset");
    if (!preset_value.is_string()) {
      fail_field(file, preset_field,
                 std::string("expected a preset name, got ") + preset_value.type_name());
    }
    const std::string name = preset_value.get<std::string>();
    const Preset* preset = find_preset(name);
    if (preset == nullptr) {
      fail_field(
          file, preset_field,
          "unknown preset '" + name + "' (nearest: " + join(nearest_preset_names(name)) + ")");
    }
    // Overridden fields below keep the preset's name: it records where the constants started.
    material = preset->material;
  }
  const std::pair<const char*, glm::vec3*> colours[] = {{"ambient", &material.ambient},
                                                        {"diffuse", &material.diffuse},
                                                        {"specular", &material.specular},
                                                        {"emission", &material.emission}};
  for (const auto& [key, target] : colours) {
    if (value.contains(key)) *target = colour_from_json(value[key], file, child_field(field, key));
  }
  if (value.contains("shininess")) {
    material.shininess =
        number_from_json(value["shininess"], file, child_field(field, "shininess"));
  }
  return material;
}

void save_materials_json(const std::string& path, const std::vector<NamedMaterial>& materials) {
  check_names(path, materials);
  nlohmann::ordered_json document;
  document["materials"] = nlohmann::ordered_json::object();
  for (const auto& [name, material] : materials) {
    document["materials"][name] = material_json<nlohmann::ordered_json>(material);
  }
  write_text_atomically(path, document.dump(2) + "\n");
}

std::vector<NamedMaterial> load_materials_json(const std::string& path) {
  // Ordered: the list comes back in the file's order, as the user arranged it.
  const nlohmann::ordered_json document = parse_ordered_json_text(read_text_file(path), path);
  if (!document.is_object()) {
    throw InputError(path, std::string("expected an object, got ") + document.type_name());
  }
  for (const auto& item : document.items()) {
    if (item.key() != "materials") {
      fail_field(path, item.key(), unknown_key_message(item.key(), {"materials"}));
    }
  }
  if (!document.contains("materials")) fail_field(path, "materials", "missing required field");
  const nlohmann::ordered_json& block = document["materials"];
  if (!block.is_object()) {
    fail_field(path, "materials", std::string("expected an object, got ") + block.type_name());
  }
  std::vector<NamedMaterial> materials;
  for (const auto& item : block.items()) {
    materials.emplace_back(item.key(), material_from_json(nlohmann::json(item.value()), path,
                                                          "materials." + item.key()));
  }
  return materials;
}

void save_mtl(const std::string& path, const std::vector<NamedMaterial>& materials) {
  check_names(path, materials);
  auto colour_line = [](const char* keyword, const glm::vec3& c) {
    return std::string(keyword) + " " + float_text(c.x) + " " + float_text(c.y) + " " +
           float_text(c.z) + "\n";
  };
  std::string text =
      "# Wavefront MTL written by gloss. Linear RGB Phong constants: Ka ambient, Kd diffuse,\n"
      "# Ks specular, Ke emission; Ns is the Phong exponent; illum 2 is Phong lighting.\n";
  for (const auto& [name, material] : materials) {
    text += "\nnewmtl " + name + "\n";
    text += colour_line("Ka", material.ambient);
    text += colour_line("Kd", material.diffuse);
    text += colour_line("Ks", material.specular);
    text += colour_line("Ke", material.emission);
    text += "Ns " + float_text(material.shininess) + "\n";
    text += "illum 2\n";
  }
  write_text_atomically(path, text);
}

std::vector<NamedMaterial> load_mtl(const std::string& path) {
  const std::string text = read_text_file(path);
  std::vector<NamedMaterial> materials;
  std::vector<int> defined_on_line;  // per material, for duplicate-name messages
  int line_number = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string trimmed = trim(line);
    if (trimmed.empty() || trimmed[0] == '#') continue;

    std::vector<Token> tokens = tokenize(line);
    const std::string keyword = lowercase(tokens[0].text);
    if (keyword == "newmtl") {
      // The name is the rest of the line: some tools write names with spaces.
      const std::string name = trim(trimmed.substr(tokens[0].text.size()));
      if (name.empty()) throw InputError(path, "newmtl without a name", line_number);
      for (std::size_t i = 0; i < materials.size(); ++i) {
        if (materials[i].first == name) {
          throw InputError(path,
                           "duplicate material '" + name + "' (first defined on line " +
                               std::to_string(defined_on_line[i]) + ")",
                           line_number);
        }
      }
      materials.emplace_back(name, Material{});
      defined_on_line.push_back(line_number);
      continue;
    }
    const bool colour = keyword == "ka" || keyword == "kd" || keyword == "ks" || keyword == "ke";
    if (!colour && keyword != "ns") continue;  // illum, d, Tr, Ni, map_Kd, bump, ...: not Phong

    // A trailing "# ..." comment is not part of the values.
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) tokens = tokenize(line.substr(0, hash));
    if (materials.empty()) {
      throw InputError(path, "'" + tokens[0].text + "' before any newmtl", line_number,
                       tokens[0].column);
    }
    Material& material = materials.back().second;
    if (keyword == "ns") {
      if (tokens.size() != 2) {
        throw InputError(
            path,
            "'" + tokens[0].text + "' expects 1 number, got " + std::to_string(tokens.size() - 1),
            line_number, tokens[0].column);
      }
      material.shininess = mtl_number(tokens[1], path, line_number);
    } else {
      const glm::vec3 value = mtl_colour(tokens, path, line_number);
      if (keyword == "ka") material.ambient = value;
      if (keyword == "kd") material.diffuse = value;
      if (keyword == "ks") material.specular = value;
      if (keyword == "ke") material.emission = value;
    }
  }
  return materials;
}

}  // namespace gloss

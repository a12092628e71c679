#include "io/material/material_io.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include <nlohmann/json.hpp>

#include "base/text/ascii.h"
#include "base/atomic_file.h"
#include "base/error.h"
#include "base/field_path.h"
#include "base/text/text_distance.h"
#include "io/json/field_json.h"
#include "io/json/json_location.h"
#include "io/json/material_json.h"
#include "io/json/name_escape.h"
#include "io/material/preset_table.h"
#include "scene/fields/fields.h"
#include "scene/fields/validation.h"

namespace gloss {

namespace {

// The keys of a material besides its fields (scene/fields/fields.h): the preset it started from,
// and its physical reference, an object of reference_fields() (docs/scene-format.md).
const char* const kPresetKey = "preset";
const char* const kReferenceKey = "reference";

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

float mtl_number(const Token& token, const std::string& path, int line) {
  char* end = nullptr;
  const double value = std::strtod(token.text.c_str(), &end);
  const bool finite = std::isfinite(value) && std::fabs(value) <= std::numeric_limits<float>::max();
  // The conversion to float is only defined in range, hence the test first; + 0 turns -0 into 0.
  const float number = finite ? static_cast<float>(value) + 0.0f : 0.0f;
  if (*end != '\0' || !finite || number < 0) {
    throw InputError(path, "expected a non-negative number, got '" + token.text + "'", line,
                     token.column);
  }
  return number;
}

// "Ka r g b" or the single-value shorthand "Ka r" (r = g = b). tokens[0] is the keyword.
glm::vec3 mtl_colour(const std::vector<Token>& tokens, const std::string& path, int line) {
  const std::string& keyword = tokens[0].text;
  if (tokens.size() > 1 &&
      (ascii_lower(tokens[1].text) == "spectral" || ascii_lower(tokens[1].text) == "xyz")) {
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

// The material field an MTL keyword (lowercase) sets.
const Field<Material>& mtl_field(const std::string& keyword) {
  const char* key = keyword == "ka"   ? "ambient"
                    : keyword == "kd" ? "diffuse"
                    : keyword == "ks" ? "specular"
                    : keyword == "ke" ? "emission"
                                      : "shininess";
  return *find_field(material_fields(), key);
}

// Names must survive a write and a read. MTL: newmtl takes the rest of the line, trimmed. JSON
// holds any name but the empty one (escaped, io/json/name_escape.h).
void check_names(const std::string& path, const std::vector<NamedMaterial>& materials, bool mtl) {
  for (std::size_t i = 0; i < materials.size(); ++i) {
    const std::string& name = materials[i].first;
    const bool mtl_safe = trim(name) == name && name.find_first_of("\r\n") == std::string::npos;
    if (name.empty() || (mtl && !mtl_safe)) {
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

nlohmann::ordered_json material_to_json(const Material& material) {
  nlohmann::ordered_json value = nlohmann::ordered_json::object();
  if (!material.preset.empty()) value[kPresetKey] = material.preset;
  write_fields(material_fields(), material, value);
  if (material.reference) {
    nlohmann::ordered_json reference = nlohmann::ordered_json::object();
    write_fields(reference_fields(), *material.reference, reference);
    // A metal's base colour is kept but unused: a file shows it only when it is not the
    // default, so a metal's block reads {"kind", "roughness"}.
    if (is_metal(material.reference->kind) &&
        material.reference->base == PhysicalReference{}.base) {
      reference.erase("base");
    }
    value[kReferenceKey] = reference;
  }
  return value;
}

Material material_from_json(const nlohmann::json& value, const std::string& file,
                            const std::string& field) {
  const JsonObjectReader reader(value, file, field,
                                allowed_keys(material_fields(), {kPresetKey, kReferenceKey}));
  Material material;
  if (reader.has(kPresetKey)) {
    const std::string name = reader.string(kPresetKey);
    const Preset* preset = find_preset(name);
    if (preset == nullptr) {
      reader.fail(kPresetKey, "unknown preset '" + name +
                                  "' (nearest: " + join(nearest_preset_names(name)) + ")");
    }
    // Overridden fields below keep the preset's name: it records where the constants started.
    material = preset->material;
  }
  read_fields(reader, material_fields(), material);
  if (reader.has(kReferenceKey)) {
    const JsonObjectReader inner(reader.required(kReferenceKey), file, reader.path(kReferenceKey),
                                 allowed_keys(reference_fields()));
    PhysicalReference reference;
    read_fields(inner, reference_fields(), reference);
    material.reference = reference;
  }
  validate_material(file, field, material);
  return material;
}

void save_materials_json(const std::string& path, const std::vector<NamedMaterial>& materials) {
  check_names(path, materials, false);
  nlohmann::ordered_json document;
  document["materials"] = nlohmann::ordered_json::object();
  for (const auto& [name, material] : materials) {
    document["materials"][escape_name(name)] = material_to_json(material);
  }
  write_text_atomically(path, document.dump(2) + "\n");
}

std::vector<NamedMaterial> load_materials_json(const std::string& path) {
  // Ordered: the list comes back in the file's order, as the user arranged it.
  const nlohmann::ordered_json document = parse_ordered_json_text(read_text_file(path), path);
  const nlohmann::json top(document);
  const JsonObjectReader reader(top, path, "", {"materials"});
  const nlohmann::json& block = reader.required("materials");
  if (!block.is_object()) {
    reader.fail("materials", std::string("expected an object, got ") + block.type_name());
  }
  std::vector<NamedMaterial> materials;
  for (const auto& item : document["materials"].items()) {
    const std::string field = child_path("materials", item.key());
    if (item.key().empty()) reader.fail("materials", "a material name must not be empty");
    const std::string name = unescape_name(item.key());
    for (const NamedMaterial& earlier : materials) {
      // "\\xE6" and "\\xe6" are one name.
      if (earlier.first == name) fail_field(path, field, "duplicate material name");
    }
    materials.emplace_back(name, material_from_json(nlohmann::json(item.value()), path, field));
  }
  return materials;
}

void save_mtl(const std::string& path, const std::vector<NamedMaterial>& materials) {
  check_names(path, materials, true);
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
    const std::string keyword = ascii_lower(tokens[0].text);
    if (keyword == "newmtl") {
      // The name is the rest of the line: some tools write names with spaces.
      const std::string name = trim(trimmed.substr(tokens[0].text.size()));
      if (name.empty()) throw InputError(path, "newmtl without a name", line_number);
      // A carriage return inside a line cannot be written back to MTL (save_mtl would refuse
      // the name it read; found by fuzz/fuzz_mtl): refused here, where the file is at fault.
      if (name.find('\r') != std::string::npos) {
        throw InputError(path, "material name contains a carriage return", line_number);
      }
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
    const Field<Material>& field = mtl_field(keyword);
    FieldValue value;
    if (keyword == "ns") {
      if (tokens.size() != 2) {
        throw InputError(
            path,
            "'" + tokens[0].text + "' expects 1 number, got " + std::to_string(tokens.size() - 1),
            line_number, tokens[0].column);
      }
      value.x = mtl_number(tokens[1], path, line_number);
    } else {
      value.v = mtl_colour(tokens, path, line_number);
    }
    const FieldProblem problem = field_problem(field, value);
    if (!problem.message.empty()) {
      throw InputError(path, "'" + tokens[0].text + "' " + problem.message, line_number,
                       tokens[0].column);
    }
    field.set(material, value);
  }
  return materials;
}

}  // namespace gloss

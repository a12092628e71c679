#include "io/material/preset_table.h"

#include <cmath>
#include <cstdlib>

#include "base/assets.h"
#include "base/atomic_file.h"
#include "base/error.h"
#include "base/text/text_distance.h"

namespace gloss {

namespace {

const char* const expected_header = "name,ar,ag,ab,dr,dg,db,sr,sg,sb,shininess_raw";
constexpr int field_count = 11;  // name, 3 ambient, 3 diffuse, 3 specular, shininess_raw

// A comma-separated field and the 1-based column it starts at, for error positions.
struct Field {
  std::string text;
  int column = 1;
};

std::vector<Field> split_fields(const std::string& line) {
  std::vector<Field> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::size_t end = comma == std::string::npos ? line.size() : comma;
    fields.push_back({line.substr(start, end - start), static_cast<int>(start) + 1});
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

bool is_preset_name(const std::string& name) {
  if (name.empty()) return false;
  for (const char c : name) {
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
  }
  return true;
}

// A table value: finite, non-negative and representable as a float.
float parse_value(const Field& field, const std::string& path, int line) {
  const char* begin = field.text.c_str();
  char* end = nullptr;
  const double value = field.text.empty() ? 0.0 : std::strtod(begin, &end);
  if (field.text.empty() || *end != '\0' || !std::isfinite(value) ||
      !std::isfinite(static_cast<float>(value))) {
    throw InputError(path, "expected a number, got '" + field.text + "'", line, field.column);
  }
  if (value < 0) {
    throw InputError(path, "negative value " + field.text, line, field.column);
  }
  return static_cast<float>(value);
}

Preset parse_row(const std::string& text, const std::string& path, int line) {
  const std::vector<Field> fields = split_fields(text);
  if (static_cast<int>(fields.size()) != field_count) {
    throw InputError(path,
                     "expected " + std::to_string(field_count) + " comma-separated fields, got " +
                         std::to_string(fields.size()),
                     line);
  }
  Preset preset;
  preset.name = fields[0].text;
  if (!is_preset_name(preset.name)) {
    throw InputError(path, "invalid preset name '" + preset.name + "' (use a-z, 0-9 and _)", line,
                     1);
  }
  float v[field_count - 1] = {};
  for (int i = 1; i < field_count; ++i) v[i - 1] = parse_value(fields[i], path, line);
  preset.shininess_raw = v[9];
  // The table's shininess is a fraction of OpenGL's maximum exponent, 128.
  if (preset.shininess_raw > 1.0f) {
    throw InputError(path, "shininess_raw must be a fraction in [0, 1], got " + fields[10].text,
                     line, fields[10].column);
  }
  Material& m = preset.material;
  m.ambient = glm::vec3(v[0], v[1], v[2]);
  m.diffuse = glm::vec3(v[3], v[4], v[5]);
  m.specular = glm::vec3(v[6], v[7], v[8]);
  m.emission = glm::vec3(0.0f);
  m.shininess = preset.shininess_raw * 128.0f;
  m.preset = preset.name;
  return preset;
}

}  // namespace

std::vector<Preset> load_preset_table(const std::string& path) {
  const std::string text = read_text_file(path);
  std::vector<Preset> presets;
  bool header_seen = false;
  int line_number = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();  // CRLF files
    if (line.empty() || line[0] == '#') continue;               // blank lines and the source note
    if (!header_seen) {
      if (line != expected_header) {
        throw InputError(path, "expected the header '" + std::string(expected_header) + "'",
                         line_number);
      }
      header_seen = true;
      continue;
    }
    Preset preset = parse_row(line, path, line_number);
    for (const Preset& earlier : presets) {
      if (earlier.name == preset.name) {
        throw InputError(path, "duplicate preset '" + preset.name + "'", line_number);
      }
    }
    presets.push_back(std::move(preset));
  }
  if (presets.empty()) throw InputError(path, "no presets in the table");
  return presets;
}

const std::vector<Preset>& preset_table() {
  // Initialised once, thread-safe (C++11 static initialisation); a failed load is retried on the
  // next call because the exception leaves the static uninitialised.
  static const std::vector<Preset> table =
      load_preset_table(asset_path("materials/opengl-vrml.csv"));
  return table;
}

const Preset* find_preset(const std::string& name) {
  for (const Preset& preset : preset_table()) {
    if (preset.name == name) return &preset;
  }
  return nullptr;
}

std::vector<std::string> nearest_preset_names(const std::string& name, std::size_t max_count) {
  std::vector<std::string> names;
  for (const Preset& preset : preset_table()) names.push_back(preset.name);
  return nearest_words(name, names, max_count);
}

}  // namespace gloss

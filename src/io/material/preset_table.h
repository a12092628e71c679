#pragma once
// The 24 OpenGL/VRML material presets, read at run time from assets/materials/opengl-vrml.csv.
#include <string>
#include <vector>

#include "scene/material.h"

namespace gloss {

struct Preset {
  std::string name;         // lowercase, '_' for spaces: "gold", "black_plastic"
  Material material;        // shininess already x128; emission 0; preset = name
  float shininess_raw = 0;  // the table's fraction, as printed in the table
};

// Parses the CSV ('#' comment lines, a header line, then rows). Throws InputError naming the
// file and line on a malformed row.
std::vector<Preset> load_preset_table(const std::string& path);

// The table from the shipped assets, loaded once (thread-safe) and kept.
const std::vector<Preset>& preset_table();

// The preset called name, or nullptr.
const Preset* find_preset(const std::string& name);

// Up to max_count preset names closest to name by edit distance, nearest first.
std::vector<std::string> nearest_preset_names(const std::string& name, std::size_t max_count = 3);

}  // namespace gloss

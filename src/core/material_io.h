#pragma once
// Saving and loading materials: gloss's JSON form and Wavefront MTL, the format every 3D tool
// reads for Phong materials (Ka, Kd, Ks, Ke, Ns).
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "material.h"

namespace gloss {

using NamedMaterial = std::pair<std::string, Material>;

// The JSON object of a material as in a scene's "materials" block (all fields written).
nlohmann::json material_to_json(const Material& material);
// Parses a material object: {"preset": NAME, ...overrides} or explicit fields. 'where' names the
// file and field for errors (InputError).
Material material_from_json(const nlohmann::json& value, const std::string& file,
                            const std::string& field);

// A file holding {"materials": {name: material, ...}}; writes atomically.
void save_materials_json(const std::string& path, const std::vector<NamedMaterial>& materials);
std::vector<NamedMaterial> load_materials_json(const std::string& path);

// Wavefront MTL: newmtl, Ka, Kd, Ks, Ke, Ns (illum 2). Writes atomically.
void save_mtl(const std::string& path, const std::vector<NamedMaterial>& materials);
std::vector<NamedMaterial> load_mtl(const std::string& path);

}  // namespace gloss

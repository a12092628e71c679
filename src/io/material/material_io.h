#pragma once
// Saving and loading materials: gloss's JSON form and Wavefront MTL, the format every 3D tool
// reads for Phong materials (Ka, Kd, Ks, Ke, Ns).
#include <string>
#include <utility>
#include <vector>

#include "scene/material.h"

namespace gloss {

using NamedMaterial = std::pair<std::string, Material>;

// A file holding {"materials": {name: material, ...}}; writes atomically.
void save_materials_json(const std::string& path, const std::vector<NamedMaterial>& materials);
std::vector<NamedMaterial> load_materials_json(const std::string& path);

// Wavefront MTL: newmtl, Ka, Kd, Ks, Ke, Ns (illum 2). Writes atomically.
void save_mtl(const std::string& path, const std::vector<NamedMaterial>& materials);
std::vector<NamedMaterial> load_mtl(const std::string& path);

}  // namespace gloss

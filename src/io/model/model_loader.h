#pragma once
// Triangle models from files through assimp, the one import path for every format gloss reads:
// Wavefront OBJ (with its MTL), Stanford PLY, STL (ASCII and binary) and glTF 2.0 (.gltf, .glb).
#include <string>
#include <vector>

#include "scene/geometry/mesh.h"
#include "scene/material.h"
#include "scene/scene.h"

namespace gloss {

struct ModelOptions {
  // false: no vertex normals at all, every triangle flat (file normals are ignored).
  bool smooth = true;
  // Degrees, 0..180, used only for the meshes that have no normals in the file
  // (kDefaultCreaseAngle, scene/scene.h).
  float crease_angle = kDefaultCreaseAngle;
};

struct ModelPart {
  std::string material_name;  // the file's material of this part, empty when none
  Mesh mesh;                  // model space (node transforms applied); normals when smooth
};

struct Model {
  std::vector<ModelPart> parts;             // one per material used
  std::vector<std::string> material_names;  // the file's materials, parallel to materials
  std::vector<Material> materials;          // Ka, Kd, Ks, Ke, Ns (docs/scene-format.md)
  std::vector<std::string> warnings;        // e.g. degenerate triangles dropped
};

// Whether path ends in an extension load_model reads (.obj .ply .stl .gltf .glb, any case).
bool is_model_file(const std::string& path);

// The extensions load_model reads, lower case with the dot, for file dialogs.
const std::vector<std::string>& model_extensions();

// Throws InputError naming the file (and the line where the format's reader gives one) for a
// missing file, an unknown extension, anything assimp refuses, and a model without triangles.
Model load_model(const std::string& path, const ModelOptions& options = {});

}  // namespace gloss

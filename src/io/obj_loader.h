#pragma once
// Wavefront OBJ meshes with their MTL, through tinyobjloader.
#include <string>
#include <vector>

#include "scene/material.h"
#include "scene/mesh.h"

namespace gloss {

struct ObjPart {
  std::string material_name;  // the MTL material of this part, empty when none
  Mesh mesh;                  // model space; smooth when the file has normals
};

struct ObjModel {
  std::vector<ObjPart> parts;               // one per material used, in file order
  std::vector<std::string> material_names;  // MTL materials, parallel to materials
  std::vector<Material> materials;          // Ka, Kd, Ks, Ke, Ns
  std::vector<std::string> warnings;        // e.g. degenerate triangles dropped
};

// Throws InputError for a missing file, garbage, out-of-range indices or no faces. A file
// without normals gets normals averaged from its faces when smooth is requested.
ObjModel load_obj(const std::string& path, bool smooth = true);

}  // namespace gloss

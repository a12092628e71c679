#pragma once
// Triangle models from files through assimp, the one import path for every format gloss reads:
// Wavefront OBJ (with its MTL), Stanford PLY, STL (ASCII and binary) and glTF 2.0 (.gltf, .glb).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

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
  // Read the images the materials name (model_maps.h) against this budget (0: the memory
  // budget); false: the materials come untextured.
  bool read_maps = true;
  std::uint64_t map_budget_bytes = 0;
};

// A texture a material of the file names, as the model library reports it; model_maps.h turns
// these into the material's maps.
struct ModelTextureRef {
  int type = 0;      // assimp's aiTextureType
  std::string path;  // as the file gives it; "*N" names an image inside the file
  int uv_set = 0;
  int wrap_u = 0, wrap_v = 0;  // assimp's aiTextureMapMode (glTF samplers)
  bool transformed = false;    // a KHR_texture_transform, as assimp's aiUVTransform:
  float translation[2] = {0.0f, 0.0f}, scaling[2] = {1.0f, 1.0f}, rotation = 0.0f;
  float strength = 1.0f;  // glTF normal texture scale, occlusion strength
};

// What a file's material asks for besides its constants.
struct ModelFileMaterial {
  std::vector<ModelTextureRef> textures;
  bool gltf = false;            // a glTF metallic-roughness material
  glm::vec4 base_colour{1.0f};  // glTF baseColorFactor
  float metallic = 1.0f, roughness = 1.0f;
  std::string alpha_mode;  // glTF: "OPAQUE", "MASK", "BLEND"
  float alpha_cutoff = 0.5f;
  bool gloss_exact = false;  // the Phong constants came exactly from gloss's extras
  // glTF without extras: the Phong lobe's error against the metallic-roughness lobe
  // (physical/lobe_metrics.h, l2 relative) for assimp's rule and for the fit; the fit's
  // constants are taken when it is closer (fitted) and no metallic-roughness texture varies
  // them per texel. -1: not measured.
  double rule_residual = -1.0, fit_residual = -1.0;
  bool fitted = false;
};

// An image inside the file (a .glb's buffer, a data: URI).
struct ModelEmbeddedImage {
  std::string name;   // "*N", as materials name it
  std::string bytes;  // the compressed image file (PNG, JPEG); empty if not one
};

struct ModelPart {
  std::string material_name;  // the file's material of this part, empty when none
  Mesh mesh;                  // model space (node transforms applied); normals when smooth
};

struct Model {
  std::vector<ModelPart> parts;             // one per material used
  std::vector<std::string> material_names;  // the file's materials, parallel to materials
  // Ka, Kd, Ks, Ke, Ns (docs/scene-format.md) and their maps; a map's file is relative to the
  // model's folder, or MODEL#MATERIAL/SLOT for an image inside the model or one gloss made from
  // the model's (io/model/model_maps.h).
  std::vector<Material> materials;
  std::vector<ModelFileMaterial> file_materials;  // parallel to materials
  std::vector<ModelEmbeddedImage> embedded;
  int exact_materials = 0;      // materials read exactly from gloss's glTF extras
  std::uint64_t map_bytes = 0;  // what the maps read took (textures already in memory not counted)
  std::vector<std::string> notes;     // e.g. a glTF material read as the fitted Phong, its error
  std::vector<std::string> warnings;  // e.g. degenerate triangles dropped, a map missing
  // What the file asks for that gloss cannot use (an unknown map option, alpha blending, a
  // missing image): the editor's notice lists these. Each is also a warning.
  std::vector<std::string> unused;
};

// Whether path ends in an extension load_model reads (.obj .ply .stl .gltf .glb, any case).
bool is_model_file(const std::string& path);

// The extensions load_model reads, lower case with the dot, for file dialogs.
const std::vector<std::string>& model_extensions();

// Throws InputError naming the file (and the line where the format's reader gives one) for a
// missing file, an unknown extension, anything assimp refuses, and a model without triangles.
Model load_model(const std::string& path, const ModelOptions& options = {});

}  // namespace gloss

#include "io/model/model_loader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/mesh.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <glm/geometric.hpp>

#include "base/text/ascii.h"
#include "base/error.h"
#include "io/model/gltf_extras.h"
#include "io/model/model_maps.h"
#include "io/model/model_material.h"
#include "io/model/model_process.h"
#include "scene/geometry/tangent_space.h"

namespace gloss {

namespace {

// assimp's messages are sometimes several lines; an InputError is one. Where the message names
// a line ("line 12", "at line 12") its number is kept, else 0.
std::string first_line(const std::string& text) {
  std::string line = text.substr(0, text.find_first_of("\r\n"));
  return line.empty() ? "cannot import" : line;
}

const char* const kNoTriangles = "no triangles (only points or lines, or empty)";

// assimp's reasons for a scene without triangle meshes (from the validation step, or from
// SortByPType after removing points and lines) say the same thing in terms of its own structures.
std::string reason(const std::string& message) {
  for (const char* empty : {"No meshes remaining", "mNumMeshes is 0", "contains no faces",
                            "contains no vertices", "has no faces"}) {
    if (message.find(empty) != std::string::npos) return kNoTriangles;
  }
  return first_line(message);
}

int line_of(const std::string& message) {
  for (std::size_t at = message.find("line "); at != std::string::npos;
       at = message.find("line ", at + 1)) {
    const char* digits = message.c_str() + at + 5;
    if (std::isdigit(static_cast<unsigned char>(*digits))) return std::atoi(digits);
  }
  return 0;
}

// assimp 5.2.5's OBJ reader skips `s` statements (ObjFileParser::skipGroupNumber), so smoothing
// groups never reach its output. The one case the crease angle cannot stand in for is a file
// whose every `s` turns smoothing off: it asks for flat faces even where they meet at small
// angles. This scan finds that case; it reads only the first word of each line, nothing else.
bool obj_smoothing_all_off(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  bool any = false;
  for (std::string line; std::getline(in, line);) {
    std::size_t i = line.find_first_not_of(" \t");
    if (i == std::string::npos || line[i] != 's' || i + 1 >= line.size() ||
        (line[i + 1] != ' ' && line[i + 1] != '\t')) {
      continue;
    }
    const std::size_t start = line.find_first_not_of(" \t", i + 1);
    const std::size_t end = line.find_first_of(" \t\r#", start);
    const std::string group =
        start == std::string::npos
            ? ""
            : line.substr(start, end == std::string::npos ? end : end - start);
    if (group != "off" && group != "0") return false;
    any = true;
  }
  return any;
}

// A normal array is usable when every normal can be normalised; otherwise the whole array is
// dropped so that the crease-angle step computes the mesh's normals from its faces instead.
bool normals_usable(const aiMesh& mesh) {
  for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
    const aiVector3D& n = mesh.mNormals[v];
    const double len = std::sqrt(double(n.x) * n.x + double(n.y) * n.y + double(n.z) * n.z);
    if (!(len > 0.0) || !std::isfinite(len)) return false;
  }
  return true;
}

// Tangents go with the normals they were made for.
void drop_normals(aiMesh& mesh) {
  delete[] mesh.mNormals;
  mesh.mNormals = nullptr;
  delete[] mesh.mTangents;
  delete[] mesh.mBitangents;
  mesh.mTangents = mesh.mBitangents = nullptr;
}

// GenSmoothNormals writes each face's normal into its corners' vertices, so it needs one vertex
// per polygon corner (assimp's "verbose" format). The PLY and glTF readers share vertices between
// faces without saying so, and assimp's own un-sharing step is internal, not a flag: this is it,
// for a mesh that (after RemoveComponent) holds only positions, texture coordinates and faces.
// Morph targets are dropped (gloss does not animate) because their arrays follow the old vertex
// numbering.
void unshare_vertices(aiMesh& mesh) {
  unsigned corners = 0;
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) corners += mesh.mFaces[f].mNumIndices;
  auto* positions = new aiVector3D[corners];
  aiVector3D* uv[2] = {nullptr, nullptr};
  for (unsigned c = 0; c < 2; ++c) {
    if (mesh.mTextureCoords[c] != nullptr) uv[c] = new aiVector3D[corners];
  }
  unsigned next = 0;
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    aiFace& face = mesh.mFaces[f];
    for (unsigned k = 0; k < face.mNumIndices; ++k) {
      positions[next] = mesh.mVertices[face.mIndices[k]];
      for (unsigned c = 0; c < 2; ++c) {
        if (uv[c] != nullptr) uv[c][next] = mesh.mTextureCoords[c][face.mIndices[k]];
      }
      face.mIndices[k] = next++;
    }
  }
  delete[] mesh.mVertices;
  mesh.mVertices = positions;
  mesh.mNumVertices = corners;
  // Texture coordinate sets 0 and 1 follow the new numbering; anything else would not.
  for (unsigned c = 0; c < AI_MAX_NUMBER_OF_TEXTURECOORDS; ++c) {
    delete[] mesh.mTextureCoords[c];
    mesh.mTextureCoords[c] = c < 2 ? uv[c] : nullptr;
  }
  for (unsigned c = 0; c < AI_MAX_NUMBER_OF_COLOR_SETS; ++c) {
    delete[] mesh.mColors[c];
    mesh.mColors[c] = nullptr;
  }
  delete[] mesh.mTangents;
  delete[] mesh.mBitangents;
  mesh.mTangents = mesh.mBitangents = nullptr;
  for (unsigned b = 0; b < mesh.mNumBones; ++b) delete mesh.mBones[b];
  delete[] mesh.mBones;
  mesh.mBones = nullptr;
  mesh.mNumBones = 0;
  for (unsigned a = 0; a < mesh.mNumAnimMeshes; ++a) delete mesh.mAnimMeshes[a];
  delete[] mesh.mAnimMeshes;
  mesh.mAnimMeshes = nullptr;
  mesh.mNumAnimMeshes = 0;
}

glm::vec3 to_vec3(const aiVector3D& v) {
  return glm::vec3(v.x, v.y, v.z);
}

// Drops the vertices no triangle uses (after degenerate triangles were removed), keeping order.
void remove_unused_vertices(Mesh& mesh) {
  std::vector<unsigned> remap(mesh.positions.size(), ~0u);
  Mesh kept;
  for (glm::uvec3& tri : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      unsigned& index = tri[k];
      if (remap[index] == ~0u) {
        remap[index] = static_cast<unsigned>(kept.positions.size());
        kept.positions.push_back(mesh.positions[index]);
        if (mesh.smooth()) kept.normals.push_back(mesh.normals[index]);
        for (int c = 0; c < 2; ++c) {
          if (!mesh.uv[c].empty()) kept.uv[c].push_back(mesh.uv[c][index]);
        }
        if (!mesh.tangents.empty()) kept.tangents.push_back(mesh.tangents[index]);
      }
      index = remap[index];
    }
  }
  kept.triangles = std::move(mesh.triangles);
  mesh = std::move(kept);
}

// A file's tangent with its handedness: +1 where the file's bitangent agrees with
// cross(normal, tangent), -1 where it is mirrored (glTF's TANGENT.w, which assimp turns into
// the bitangent).
glm::vec4 file_tangent(const aiMesh& in, unsigned v) {
  const glm::dvec3 t(in.mTangents[v].x, in.mTangents[v].y, in.mTangents[v].z);
  const double len = glm::length(t);
  const glm::vec3 unit = len > 0.0 && std::isfinite(len) ? glm::vec3(t / len) : glm::vec3(0.0f);
  float w = 1.0f;
  if (in.mBitangents != nullptr && in.mNormals != nullptr) {
    const glm::vec3 n(in.mNormals[v].x, in.mNormals[v].y, in.mNormals[v].z);
    const glm::vec3 b(in.mBitangents[v].x, in.mBitangents[v].y, in.mBitangents[v].z);
    w = glm::dot(glm::cross(n, unit), b) < 0.0f ? -1.0f : 1.0f;
  }
  return glm::vec4(unit, w);
}

// Appends one triangulated assimp mesh. Normals are normalised in double so tiny but non-zero
// file normals do not underflow; one that still cannot be normalised (a vertex only degenerate
// faces use) takes the normal of a triangle through it.
void append_mesh(const aiMesh& in, bool with_normals, Mesh& out) {
  const auto base = static_cast<unsigned>(out.positions.size());
  for (unsigned v = 0; v < in.mNumVertices; ++v) {
    out.positions.push_back(to_vec3(in.mVertices[v]));
    for (unsigned c = 0; c < 2; ++c) {
      if (in.mTextureCoords[c] != nullptr) {
        out.uv[c].emplace_back(in.mTextureCoords[c][v].x, in.mTextureCoords[c][v].y);
      }
    }
    if (with_normals && in.mTangents != nullptr) out.tangents.push_back(file_tangent(in, v));
    if (!with_normals) continue;
    const glm::dvec3 n(in.mNormals[v].x, in.mNormals[v].y, in.mNormals[v].z);
    const double len = glm::length(n);
    out.normals.push_back(len > 0.0 && std::isfinite(len) ? glm::vec3(n / len) : glm::vec3(0.0f));
  }
  for (unsigned f = 0; f < in.mNumFaces; ++f) {
    const aiFace& face = in.mFaces[f];
    if (face.mNumIndices != 3) continue;  // points and lines were removed; kept safe anyway
    const glm::uvec3 tri(base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]);
    out.triangles.push_back(tri);
    if (!with_normals) continue;
    const glm::vec3 a = out.positions[tri.x], b = out.positions[tri.y], c = out.positions[tri.z];
    const glm::dvec3 face_n = glm::cross(glm::dvec3(b - a), glm::dvec3(c - a));
    const double len = glm::length(face_n);
    if (!(len > 0.0) || !std::isfinite(len)) continue;
    for (int k = 0; k < 3; ++k) {
      if (out.normals[tri[k]] == glm::vec3(0.0f)) out.normals[tri[k]] = glm::vec3(face_n / len);
    }
  }
}

// The importer's flags: node transforms are applied and meshes sharing a material are merged,
// and components gloss does not use are dropped. Polygons are triangulated (and points and
// lines removed) in the second pass (load_model), after vertices were un-shared, so that
// GenSmoothNormals counts each polygon once at a vertex, as for an OBJ file, whatever the format.
constexpr unsigned kImportFlags =
    aiProcess_RemoveComponent | aiProcess_PreTransformVertices | aiProcess_ValidateDataStructure;
constexpr int kRemovedComponents = aiComponent_COLORS | aiComponent_BONEWEIGHTS |
                                   aiComponent_ANIMATIONS | aiComponent_LIGHTS |
                                   aiComponent_CAMERAS;

}  // namespace

const std::vector<std::string>& model_extensions() {
  static const std::vector<std::string> extensions = {".obj", ".ply", ".stl", ".gltf", ".glb"};
  return extensions;
}

bool is_model_file(const std::string& path) {
  const std::string ext = lower_extension(path);
  const std::vector<std::string>& known = model_extensions();
  return std::find(known.begin(), known.end(), ext) != known.end();
}

namespace {
// The import proper, run in a child process by load_model (model_process.h says why).
Model import_with_assimp(const std::string& path, const ModelOptions& options) {
  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, kRemovedComponents);
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  // assimp clamps the angle to 175 degrees and smooths across every edge at that value.
  importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, options.crease_angle);
  const aiScene* scene = importer.ReadFile(path, kImportFlags);
  if (scene == nullptr) {
    const std::string message = importer.GetErrorString();
    throw InputError(path, reason(message), line_of(message));
  }

  // Normals: the file's where it has usable ones; none at all when not smooth, or for an OBJ
  // whose smoothing groups are all off; otherwise crease-angle normals from the faces.
  const bool flat =
      !options.smooth || (lower_extension(path) == ".obj" && obj_smoothing_all_off(path));
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    aiMesh& mesh = *scene->mMeshes[m];
    if (mesh.mNormals != nullptr && (flat || !normals_usable(mesh))) drop_normals(mesh);
    if (mesh.mNormals == nullptr && !flat) unshare_vertices(mesh);
  }
  // Concave polygons and ones with bridged holes become their proper triangles (assimp orders
  // the steps: Triangulate, then GenSmoothNormals, then JoinIdenticalVertices).
  // SortByPType (points and lines removed) runs here, after Triangulate: before it, it would put
  // a model's triangles and its quads into separate meshes, and normals are not smoothed across
  // meshes.
  scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_SortByPType |
                                       aiProcess_JoinIdenticalVertices |
                                       (flat ? 0u : unsigned(aiProcess_GenSmoothNormals)));
  if (scene == nullptr) {
    const std::string message = importer.GetErrorString();
    throw InputError(path, reason(message), line_of(message));
  }

  Model model;
  // gloss's own glTF files carry the exact Phong constants, found by the material's name (assimp
  // numbers glTF's materials in the order meshes first use them). It appends a default material
  // of its own (unnamed in assimp 5.2), which no part of a file whose every mesh names its
  // material uses: a glTF's materials past the file's count are it.
  const bool gltf = lower_extension(path) == ".gltf" || lower_extension(path) == ".glb";
  const GltfMaterialExtras extras = gltf ? read_gloss_extras(path) : GltfMaterialExtras{};
  std::map<unsigned, std::string> name_of;  // material index -> name, default material absent
  for (unsigned i = 0; i < scene->mNumMaterials; ++i) {
    NamedMaterial named = convert_material(*scene->mMaterials[i], i, path);
    if (extras.parsed && i >= extras.materials.size()) named.is_default = true;
    if (named.is_default) continue;
    if (const GlossExtras* found = find_gloss_extras(extras, named.name)) {
      const GlossExtras& e = *found;
      Material& m = named.material;
      m.ambient = e.ambient;
      m.diffuse = e.diffuse;
      m.specular = e.specular;
      m.emission = e.emission;
      m.shininess = e.shininess;
      named.textures.gloss_exact = true;
    }
    std::string name = named.name;
    for (int k = 2; std::count(model.material_names.begin(), model.material_names.end(), name);
         ++k) {
      name = named.name + "#" + std::to_string(k);  // glTF may repeat a name
    }
    name_of[i] = name;
    model.material_names.push_back(name);
    model.materials.push_back(named.material);
    model.file_materials.push_back(std::move(named.textures));
  }
  // Images inside the file (a .glb's buffers, data: URIs), named "*N" as the materials name them.
  for (unsigned i = 0; i < scene->mNumTextures; ++i) {
    const aiTexture& texture = *scene->mTextures[i];
    ModelEmbeddedImage image;
    image.name = "*" + std::to_string(i);
    if (texture.mHeight == 0) {  // compressed (PNG, JPEG ...): mWidth bytes
      image.bytes.assign(reinterpret_cast<const char*>(texture.pcData), texture.mWidth);
    }  // else raw texels, which no glTF or OBJ file makes: left empty, reported as unusable
    model.embedded.push_back(std::move(image));
  }

  std::map<unsigned, std::size_t> part_of;  // material index -> part
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& mesh = *scene->mMeshes[m];
    if (!(mesh.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) || mesh.mNumFaces == 0) continue;
    const auto [it, inserted] = part_of.try_emplace(mesh.mMaterialIndex, model.parts.size());
    if (inserted) {
      model.parts.emplace_back();
      const auto name = name_of.find(mesh.mMaterialIndex);
      if (name != name_of.end()) model.parts.back().material_name = name->second;
    }
    append_mesh(mesh, !flat && mesh.mNormals != nullptr, model.parts[it->second].mesh);
  }
  // A part mixing meshes with and without normals would be inconsistent: flat throughout; the
  // same for texture coordinates and tangents.
  for (ModelPart& part : model.parts) {
    Mesh& mesh = part.mesh;
    if (mesh.normals.size() != mesh.positions.size()) mesh.normals.clear();
    for (auto& uv : mesh.uv) {
      if (uv.size() != mesh.positions.size()) uv.clear();
    }
    if (mesh.uv[0].empty()) mesh.uv[1].clear();
    if (mesh.tangents.size() != mesh.positions.size() || !mesh.smooth()) mesh.tangents.clear();
  }

  std::size_t dropped = 0;
  for (ModelPart& part : model.parts) {
    dropped += drop_degenerate_triangles(part.mesh);
    remove_unused_vertices(part.mesh);
    // The file's tangents where it gives them, else MikkTSpace's (the convention normal maps
    // are baked in).
    if (part.mesh.tangents.empty()) generate_tangents(part.mesh);
  }
  if (dropped > 0) {
    model.warnings.push_back(path + ": dropped " + std::to_string(dropped) +
                             " degenerate triangles");
  }
  if (model.parts.empty()) throw InputError(path, kNoTriangles);
  // Degenerate triangles never make a scene fail (docs/scene-format.md): a model whose every
  // triangle is degenerate loads as empty parts, with the warning, and renders as nothing.
  const bool all_empty = std::all_of(model.parts.begin(), model.parts.end(),
                                     [](const ModelPart& p) { return p.mesh.triangles.empty(); });
  if (!all_empty) {
    model.parts.erase(std::remove_if(model.parts.begin(), model.parts.end(),
                                     [](const ModelPart& p) { return p.mesh.triangles.empty(); }),
                      model.parts.end());
  }
  return model;
}
}  // namespace

Model load_model(const std::string& path, const ModelOptions& options) {
  std::error_code fs_error;
  if (std::filesystem::is_directory(path, fs_error)) throw InputError(path, "is a folder");
  if (!std::ifstream(path, std::ios::binary)) throw InputError(path, "cannot open file");
  if (!is_model_file(path)) {
    throw InputError(path, "unknown model format '" + lower_extension(path) +
                               "' (gloss reads .obj, .ply, .stl, .gltf and .glb)");
  }
  if (!(options.crease_angle >= 0.0f && options.crease_angle <= 180.0f)) {
    throw InputError(path, "crease angle must be 0..180 degrees");
  }
  Model model = import_in_child_process(
      path, [&options](const std::string& file) { return import_with_assimp(file, options); });
  // The child is this program, but what comes back is checked as any input: arrays that do not
  // match their mesh are dropped rather than indexed.
  for (ModelPart& part : model.parts) {
    Mesh& mesh = part.mesh;
    for (auto& uv : mesh.uv) {
      if (uv.size() != mesh.positions.size()) uv.clear();
    }
    if (mesh.tangents.size() != mesh.positions.size()) mesh.tangents.clear();
  }
  model.file_materials.resize(model.materials.size());
  model.exact_materials =
      static_cast<int>(std::count_if(model.file_materials.begin(), model.file_materials.end(),
                                     [](const ModelFileMaterial& m) { return m.gloss_exact; }));
  fit_metal_rough_materials(model);
  if (options.read_maps) read_model_maps(path, model, options);
  return model;
}

}  // namespace gloss

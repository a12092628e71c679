#pragma once
// The binary side of a glTF 2.0 file being written: one buffer, views into it aligned to 4
// bytes, and accessors over them (the JSON arrays `bufferViews` and `accessors`), and the
// triangle meshes of a scene's objects as primitives over that buffer. Private to export/.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include "scene/geometry/mesh.h"

namespace gloss {

class GltfBuffer {
 public:
  // A view of bytes (target: 34962 ARRAY_BUFFER, 34963 ELEMENT_ARRAY_BUFFER, 0 none); returns
  // its index.
  int add_view(const void* data, std::size_t bytes, int target);
  // Accessors of float vectors (with min and max where glTF requires them: positions) and of
  // unsigned 32-bit indices.
  int add_vec2(const std::vector<glm::vec2>& values);
  int add_vec3(const std::vector<glm::vec3>& values, bool bounds);
  int add_vec4(const std::vector<glm::vec4>& values);
  int add_indices(const std::vector<glm::uvec3>& triangles);

  const std::string& bytes() const { return bytes_; }
  nlohmann::json& views() { return views_; }
  nlohmann::json& accessors() { return accessors_; }

 private:
  int add_accessor(int view, std::size_t count, const char* type, int component);
  std::string bytes_;
  nlohmann::json views_ = nlohmann::json::array();
  nlohmann::json accessors_ = nlohmann::json::array();
};

// A mesh's primitive attributes written to buffer: POSITION, NORMAL (smooth meshes),
// TEXCOORD_0/1 (v flipped: glTF's origin is the image's top left, gloss's v grows up) and
// TANGENT (when the mesh has them and normals); normals and tangents renormalised in float.
nlohmann::json mesh_primitive(GltfBuffer& buffer, const Mesh& mesh, int material);

// A unit sphere at the origin as gloss maps it (texture/sphere_mapping.h): `segments` around,
// segments / 2 from pole to pole, smooth normals, (u, v) and tangents; no degenerate triangles
// at the poles.
Mesh unit_sphere(int segments);

}  // namespace gloss

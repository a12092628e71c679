#include "export/gltf_buffer.h"

#include <cmath>
#include <cstring>
#include <limits>

#include <glm/geometric.hpp>

namespace gloss {

namespace {

constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr double kPi = 3.14159265358979323846;

}  // namespace

int GltfBuffer::add_view(const void* data, std::size_t bytes, int target) {
  while (bytes_.size() % 4 != 0) bytes_.push_back('\0');
  nlohmann::json view = {{"buffer", 0}, {"byteOffset", bytes_.size()}, {"byteLength", bytes}};
  if (target != 0) view["target"] = target;
  bytes_.append(static_cast<const char*>(data), bytes);
  views_.push_back(view);
  return static_cast<int>(views_.size()) - 1;
}

int GltfBuffer::add_accessor(int view, std::size_t count, const char* type, int component) {
  accessors_.push_back(
      {{"bufferView", view}, {"componentType", component}, {"count", count}, {"type", type}});
  return static_cast<int>(accessors_.size()) - 1;
}

int GltfBuffer::add_vec2(const std::vector<glm::vec2>& values) {
  const int view = add_view(values.data(), values.size() * sizeof(glm::vec2), kArrayBuffer);
  return add_accessor(view, values.size(), "VEC2", kFloat);
}

int GltfBuffer::add_vec3(const std::vector<glm::vec3>& values, bool bounds) {
  const int view = add_view(values.data(), values.size() * sizeof(glm::vec3), kArrayBuffer);
  const int accessor = add_accessor(view, values.size(), "VEC3", kFloat);
  if (bounds && !values.empty()) {
    glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-lo);
    for (const glm::vec3& v : values) lo = glm::min(lo, v), hi = glm::max(hi, v);
    accessors_[accessor]["min"] = {lo.x, lo.y, lo.z};
    accessors_[accessor]["max"] = {hi.x, hi.y, hi.z};
  }
  return accessor;
}

int GltfBuffer::add_vec4(const std::vector<glm::vec4>& values) {
  const int view = add_view(values.data(), values.size() * sizeof(glm::vec4), kArrayBuffer);
  return add_accessor(view, values.size(), "VEC4", kFloat);
}

int GltfBuffer::add_indices(const std::vector<glm::uvec3>& triangles) {
  const int view =
      add_view(triangles.data(), triangles.size() * sizeof(glm::uvec3), kElementArrayBuffer);
  return add_accessor(view, triangles.size() * 3, "SCALAR", kUnsignedInt);
}

nlohmann::json mesh_primitive(GltfBuffer& buffer, const Mesh& mesh, int material) {
  nlohmann::json attributes;
  attributes["POSITION"] = buffer.add_vec3(mesh.positions, true);
  if (mesh.smooth()) {
    std::vector<glm::vec3> normals(mesh.normals.size());
    for (std::size_t i = 0; i < normals.size(); ++i) normals[i] = glm::normalize(mesh.normals[i]);
    attributes["NORMAL"] = buffer.add_vec3(normals, false);
    if (mesh.tangents.size() == mesh.positions.size()) {
      std::vector<glm::vec4> tangents(mesh.tangents.size());
      for (std::size_t i = 0; i < tangents.size(); ++i) {
        const glm::vec4& t = mesh.tangents[i];
        tangents[i] = glm::vec4(glm::normalize(glm::vec3(t)), t.w < 0.0f ? -1.0f : 1.0f);
      }
      attributes["TANGENT"] = buffer.add_vec4(tangents);
    }
  }
  for (int set = 0; set < 2; ++set) {
    if (mesh.uv[set].size() != mesh.positions.size()) continue;
    std::vector<glm::vec2> uv(mesh.uv[set].size());
    for (std::size_t i = 0; i < uv.size(); ++i)
      uv[i] = {mesh.uv[set][i].x, 1.0f - mesh.uv[set][i].y};
    attributes["TEXCOORD_" + std::to_string(set)] = buffer.add_vec2(uv);
  }
  return {{"attributes", attributes},
          {"indices", buffer.add_indices(mesh.triangles)},
          {"material", material}};
}

Mesh unit_sphere(int segments) {
  const int around = segments, rings = segments / 2;
  Mesh mesh;
  for (int j = 0; j <= rings; ++j) {
    const double v = static_cast<double>(j) / rings;
    const double latitude = kPi * (v - 0.5);
    for (int i = 0; i <= around; ++i) {
      const double u = static_cast<double>(i) / around;
      const double phi = 2.0 * kPi * (u - 0.5);  // atan2(x, z) of sphere_mapping.h
      const glm::dvec3 d(std::cos(latitude) * std::sin(phi), std::sin(latitude),
                         std::cos(latitude) * std::cos(phi));
      mesh.positions.push_back(glm::vec3(d));
      mesh.normals.push_back(glm::vec3(d));
      mesh.uv[0].push_back({static_cast<float>(u), static_cast<float>(v)});
      mesh.tangents.push_back(
          {static_cast<float>(std::cos(phi)), 0.0f, static_cast<float>(-std::sin(phi)), 1.0f});
    }
  }
  const auto at = [&](int i, int j) { return static_cast<unsigned>(j * (around + 1) + i); };
  for (int j = 0; j < rings; ++j) {
    for (int i = 0; i < around; ++i) {
      // Counter-clockwise seen from outside: u grows towards +x, v upwards.
      if (j != 0) mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      if (j != rings - 1) mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return mesh;
}

}  // namespace gloss

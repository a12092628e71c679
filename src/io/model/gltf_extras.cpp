#include "io/model/gltf_extras.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

namespace gloss {

namespace {

std::uint32_t u32(const std::string& bytes, std::size_t at) {
  std::uint32_t x = 0;
  std::memcpy(&x, bytes.data() + at, 4);  // glTF is little-endian, as x86-64
  return x;
}

// The JSON text of a .gltf, or of a .glb's first chunk; "" when the file is neither.
std::string gltf_json_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() >= 20 && u32(bytes, 0) == 0x46546C67u) {  // "glTF"
    const std::uint32_t length = u32(bytes, 12);
    if (u32(bytes, 16) != 0x4E4F534Au || length > bytes.size() - 20) return "";
    return bytes.substr(20, length);
  }
  return bytes;
}

bool read_colour(const nlohmann::json& j, const char* key, glm::vec3& out) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_array() || it->size() != 3) return false;
  for (int c = 0; c < 3; ++c) {
    if (!(*it)[c].is_number()) return false;
    out[c] = (*it)[c].get<float>();
    if (!std::isfinite(out[c]) || out[c] < 0.0f) return false;
  }
  return true;
}

}  // namespace

GltfMaterialExtras read_gloss_extras(const std::string& path) {
  GltfMaterialExtras out;
  const nlohmann::json doc = nlohmann::json::parse(gltf_json_text(path), nullptr, false);
  if (!doc.is_object()) return out;
  out.parsed = true;
  if (!doc.contains("materials") || !doc["materials"].is_array()) return out;
  for (const nlohmann::json& material : doc["materials"]) {
    std::optional<GlossExtras> entry;
    const nlohmann::json* gloss = nullptr;
    if (material.is_object() && material.contains("extras") && material["extras"].is_object() &&
        material["extras"].contains("gloss") && material["extras"]["gloss"].is_object()) {
      gloss = &material["extras"]["gloss"];
    }
    GlossExtras e;
    if (gloss != nullptr && read_colour(*gloss, "ambient", e.ambient) &&
        read_colour(*gloss, "diffuse", e.diffuse) && read_colour(*gloss, "specular", e.specular) &&
        read_colour(*gloss, "emission", e.emission) && gloss->contains("shininess") &&
        (*gloss)["shininess"].is_number()) {
      e.shininess = (*gloss)["shininess"].get<float>();
      if (material.contains("name") && material["name"].is_string()) e.name = material["name"];
      if (std::isfinite(e.shininess) && e.shininess >= 0.0f) entry = e;
    }
    out.materials.push_back(entry);
  }
  return out;
}

const GlossExtras* find_gloss_extras(const GltfMaterialExtras& extras, const std::string& name) {
  const GlossExtras* found = nullptr;
  int named = 0;
  for (const std::optional<GlossExtras>& e : extras.materials) {
    if (!e || e->name != name) continue;
    found = &*e;
    ++named;
  }
  return named == 1 ? found : nullptr;
}

}  // namespace gloss

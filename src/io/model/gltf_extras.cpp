#include "io/model/gltf_extras.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>

#include <nlohmann/json.hpp>

#include "base/error.h"

namespace gloss {

namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67u;   // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534Au;  // "JSON"

std::uint32_t u32(const char* bytes) {
  std::uint32_t x = 0;
  std::memcpy(&x, bytes, 4);  // glTF is little-endian, as x86-64
  return x;
}

// The JSON text of a .gltf (the whole file), or of a .glb's first chunk, read alone: the 12-byte
// header and the chunk's 8-byte header, then only its length in bytes (the buffers after it are
// not read). Throws InputError naming the file for a .glb cut short or whose first chunk is not
// JSON or does not fit the file.
std::string gltf_json_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open file");
  char header[20];
  in.read(header, sizeof header);
  const auto got = static_cast<std::size_t>(in.gcount());
  if (got < 4 || u32(header) != kGlbMagic) {
    in.clear();
    in.seekg(0);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }
  if (got < sizeof header) {
    throw InputError(
        path, "GLB cut short: " + std::to_string(got) + " bytes, fewer than its 20-byte header");
  }
  if (u32(header + 16) != kJsonChunk) throw InputError(path, "GLB's first chunk is not JSON");
  const std::uint32_t length = u32(header + 12);
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error || length > size - sizeof header) {
    throw InputError(
        path, "GLB's JSON chunk of " + std::to_string(length) +
                  " bytes runs past the end of the file (" +
                  (error ? std::string("size unknown") : std::to_string(size) + " bytes") + ")");
  }
  std::string text(length, '\0');
  in.read(text.data(), length);
  if (static_cast<std::size_t>(in.gcount()) != length) {
    throw InputError(path, "GLB's JSON chunk cut short while reading it");
  }
  return text;
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

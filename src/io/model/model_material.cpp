#include "io/model/model_material.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <assimp/material.h>

#include <glm/common.hpp>

#include "base/error.h"

namespace gloss {

namespace {

bool get_colour(const aiMaterial& m, const char* key, unsigned type, unsigned index,
                glm::vec3& out) {
  aiColor4D c;
  if (m.Get(key, type, index, c) != AI_SUCCESS) return false;
  out = glm::vec3(c.r, c.g, c.b);
  return true;
}

bool get_float(const aiMaterial& m, const char* key, unsigned type, unsigned index, float& out) {
  ai_real value;
  if (m.Get(key, type, index, value) != AI_SUCCESS) return false;
  out = static_cast<float>(value);
  return true;
}

// assimp's stand-in for a part without a material of its own, where it is not named
// AI_DEFAULT_MATERIAL_NAME: an unnamed white material with no texture (the PLY reader's ka = kd =
// ks = 1; the glTF 2.0 reader's default material, base colour 1, metallic 1, roughness 1, the
// glTF defaults, which the glTF specification says a primitive without a material uses).
bool is_stand_in_white(const aiMaterial& m) {
  aiString name;
  if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS && name.length > 0) return false;
  for (unsigned p = 0; p < m.mNumProperties; ++p) {
    if (std::string(m.mProperties[p]->mKey.C_Str()).rfind("$tex.", 0) == 0) return false;
  }
  const glm::vec3 white(1.0f);
  glm::vec3 c;
  if (!get_colour(m, AI_MATKEY_COLOR_DIFFUSE, c) || c != white) return false;
  for (const char* key : {"$clr.ambient", "$clr.specular", "$clr.base"}) {
    if (get_colour(m, key, 0, 0, c) && c != white) return false;
  }
  if (get_colour(m, AI_MATKEY_COLOR_EMISSIVE, c) && c != glm::vec3(0.0f)) return false;
  float f = 1.0f;
  if (get_float(m, AI_MATKEY_METALLIC_FACTOR, f) && f != 1.0f) return false;
  if (get_float(m, AI_MATKEY_ROUGHNESS_FACTOR, f) && f != 1.0f) return false;
  return true;
}

}  // namespace

NamedMaterial convert_material(const aiMaterial& in, unsigned index,
                               const std::string& model_file) {
  NamedMaterial out;
  aiString name;
  if (in.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();
  out.is_default = out.name == AI_DEFAULT_MATERIAL_NAME || is_stand_in_white(in);
  if (out.name.empty()) out.name = "material" + std::to_string(index);

  Material& m = out.material;
  m.preset.clear();
  glm::vec3 base(0.0f);
  float metallic = 1.0f, roughness = 1.0f;  // the glTF 2.0 defaults
  const bool pbr = get_colour(in, AI_MATKEY_BASE_COLOR, base) |
                   get_float(in, AI_MATKEY_METALLIC_FACTOR, metallic) |
                   get_float(in, AI_MATKEY_ROUGHNESS_FACTOR, roughness);
  if (!get_colour(in, AI_MATKEY_COLOR_DIFFUSE, m.diffuse) && pbr) m.diffuse = base;
  if (!get_colour(in, AI_MATKEY_COLOR_AMBIENT, m.ambient) && pbr) m.ambient = m.diffuse;
  if (!get_colour(in, AI_MATKEY_COLOR_SPECULAR, m.specular) && pbr) {
    const float r = std::clamp(roughness, 0.0f, 1.0f);
    m.specular =
        glm::mix(glm::vec3(0.04f), m.diffuse, std::clamp(metallic, 0.0f, 1.0f)) * (1.0f - r);
  }
  get_colour(in, AI_MATKEY_COLOR_EMISSIVE, m.emission);
  // assimp's glTF 2.0 reader gives shininess itself: 1000 (1 - roughness)^2.
  get_float(in, AI_MATKEY_SHININESS, m.shininess);

  const std::pair<const char*, glm::vec3> colours[] = {
      {"Ka", m.ambient}, {"Kd", m.diffuse}, {"Ks", m.specular}, {"Ke", m.emission}};
  for (const auto& [key, c] : colours) {
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(c[k]) || c[k] < 0.0f) {
        throw InputError(model_file, "colour components must be finite and >= 0", 0, 0,
                         "material '" + out.name + "' " + key);
      }
    }
  }
  if (!std::isfinite(m.shininess) || m.shininess < 0.0f) {
    throw InputError(model_file, "must be finite and >= 0", 0, 0, "material '" + out.name + "' Ns");
  }
  return out;
}

}  // namespace gloss

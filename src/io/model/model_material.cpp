#include "io/model/model_material.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <utility>

#include <assimp/GltfMaterial.h>
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

// assimp lists glTF's base colour texture as DIFFUSE and BASE_COLOR, and its metallic-roughness
// texture as UNKNOWN, METALNESS and DIFFUSE_ROUGHNESS: each once is enough.
constexpr aiTextureType kDuplicateTypes[] = {aiTextureType_BASE_COLOR, aiTextureType_METALNESS,
                                             aiTextureType_DIFFUSE_ROUGHNESS};

ModelFileMaterial file_material(const aiMaterial& in, bool pbr, const glm::vec3& base,
                                float metallic, float roughness) {
  ModelFileMaterial out;
  out.gltf = pbr;
  float opacity = 1.0f;
  get_float(in, AI_MATKEY_OPACITY, opacity);
  out.base_colour = glm::vec4(base, opacity);
  out.metallic = metallic;
  out.roughness = roughness;
  aiString mode;
  if (in.Get(AI_MATKEY_GLTF_ALPHAMODE, mode) == AI_SUCCESS) out.alpha_mode = mode.C_Str();
  get_float(in, AI_MATKEY_GLTF_ALPHACUTOFF, out.alpha_cutoff);
  for (int t = aiTextureType_NONE + 1; t <= AI_TEXTURE_TYPE_MAX; ++t) {
    const auto type = static_cast<aiTextureType>(t);
    if (std::find(std::begin(kDuplicateTypes), std::end(kDuplicateTypes), type) !=
        std::end(kDuplicateTypes)) {
      continue;
    }
    const unsigned count = in.GetTextureCount(type);
    for (unsigned k = 0; k < count; ++k) {
      ModelTextureRef ref;
      ref.type = t;
      aiString path;
      unsigned uv = 0;
      aiTextureMapMode modes[2] = {aiTextureMapMode_Wrap, aiTextureMapMode_Wrap};
      if (in.GetTexture(type, k, &path, nullptr, &uv, nullptr, nullptr, modes) != AI_SUCCESS) {
        continue;
      }
      ref.path = path.C_Str();
      ref.uv_set = static_cast<int>(uv);
      ref.wrap_u = modes[0];
      ref.wrap_v = modes[1];
      aiUVTransform transform;
      if (in.Get(AI_MATKEY_UVTRANSFORM(type, k), transform) == AI_SUCCESS) {
        ref.transformed = true;
        ref.translation[0] = transform.mTranslation.x;
        ref.translation[1] = transform.mTranslation.y;
        ref.scaling[0] = transform.mScaling.x;
        ref.scaling[1] = transform.mScaling.y;
        ref.rotation = transform.mRotation;
      }
      get_float(in, AI_MATKEY_GLTF_TEXTURE_SCALE(type, k), ref.strength);
      get_float(in, AI_MATKEY_GLTF_TEXTURE_STRENGTH(type, k), ref.strength);
      out.textures.push_back(ref);
    }
  }
  return out;
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
  out.textures = file_material(in, pbr, base, metallic, roughness);
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

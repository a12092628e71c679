#include "io/model/model_material.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>
#include <utility>

#include <tbb/parallel_for.h>

#include <assimp/GltfMaterial.h>
#include <assimp/material.h>

#include <glm/common.hpp>

#include "base/error.h"
#include "physical/metal_rough_fit.h"

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

void fit_metal_rough_materials(Model& model) {
  // Files repeat materials (one per part): each distinct (base, metallic, roughness) is fitted
  // once, the distinct ones in parallel.
  struct Job {
    MetalRough pbr;
    PhongFit fit;
  };
  std::vector<Job> jobs;
  std::vector<int> job_of(model.materials.size(), -1);
  for (std::size_t i = 0; i < model.materials.size(); ++i) {
    const ModelFileMaterial& f = model.file_materials[i];
    if (!f.gltf || f.gloss_exact) continue;
    MetalRough pbr;
    pbr.base_colour = glm::clamp(glm::dvec3(glm::vec3(f.base_colour)), 0.0, 1.0);
    pbr.metallic = std::clamp(static_cast<double>(f.metallic), 0.0, 1.0);
    pbr.roughness = std::clamp(static_cast<double>(f.roughness), kMinFitRoughness, 1.0);
    const auto same = std::find_if(jobs.begin(), jobs.end(), [&](const Job& j) {
      return j.pbr.base_colour == pbr.base_colour && j.pbr.metallic == pbr.metallic &&
             j.pbr.roughness == pbr.roughness;
    });
    job_of[i] = static_cast<int>(same - jobs.begin());
    if (same == jobs.end()) jobs.push_back({pbr, {}});
  }
  tbb::parallel_for(std::size_t(0), jobs.size(),
                    [&](std::size_t j) { jobs[j].fit = fit_phong_to_metal_rough(jobs[j].pbr); });
  for (std::size_t i = 0; i < model.materials.size(); ++i) {
    if (job_of[i] < 0) continue;
    ModelFileMaterial& f = model.file_materials[i];
    Material& m = model.materials[i];
    const Job& job = jobs[static_cast<std::size_t>(job_of[i])];
    f.fit_residual = job.fit.residual.l2_relative;
    f.rule_residual =
        residual_to_metal_rough(phong_lobe(m, ShadingModel::phong, false), job.pbr).l2_relative;
    const bool textured = std::any_of(f.textures.begin(), f.textures.end(), [](const auto& t) {
      return t.type == aiTextureType_UNKNOWN;  // glTF's metallic-roughness texture
    });
    if (f.fit_residual < f.rule_residual && !textured) {
      m.diffuse = glm::vec3(job.fit.lobe.kd);
      m.ambient = m.diffuse;
      m.specular = glm::vec3(job.fit.lobe.ks);
      m.shininess = static_cast<float>(job.fit.lobe.alpha);
      f.fitted = true;
    }
  }
  for (std::size_t i = 0; i < model.materials.size(); ++i) {
    const ModelFileMaterial& f = model.file_materials[i];
    if (f.fit_residual < 0.0) continue;
    char text[200];
    std::snprintf(text, sizeof text,
                  ": metallic-roughness as %s Phong (error %.3g %%; fitted %.3g %%, "
                  "assimp's rule %.3g %%)",
                  f.fitted ? "the fitted" : "assimp's rule of",
                  100.0 * (f.fitted ? f.fit_residual : f.rule_residual), 100.0 * f.fit_residual,
                  100.0 * f.rule_residual);
    model.notes.push_back("material '" + model.material_names[i] + "'" + text);
  }
}

}  // namespace gloss

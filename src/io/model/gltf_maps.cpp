// read_gltf_maps (map_reading.h): a glTF 2.0 file's textures, as assimp 5.2.5 lists them per
// material, made into gloss maps (model_maps.h says which and how).
#include <assimp/material.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

#include "io/model/map_reading.h"
#include "io/model/model_maps.h"
#include "texture/texture_lookup.h"

namespace gloss {

namespace {

constexpr float kPi = 3.14159265358979323846f;

Wrap wrap_of(int mode) {
  switch (mode) {
    case aiTextureMapMode_Clamp:
    case aiTextureMapMode_Decal:
      return Wrap::clamp;
    case aiTextureMapMode_Mirror:
      return Wrap::mirror;
    default:
      return Wrap::repeat;
  }
}

// glTF URIs are percent-encoded ("my%20texture.png").
std::string decode_uri(const std::string& uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out += static_cast<char>(std::strtol(uri.substr(i + 1, 2).c_str(), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

// KHR_texture_transform as gloss's map settings. assimp hands the extension over as an
// aiUVTransform it derived for its own conventions (its glTF importer: rotation negated, the
// translation moved so that rotation turns about the texture's centre, v flipped); that is
// undone here to the extension's offset o, rotation r and scale s, which act on glTF's (u, v)
// (v down) as uv' = T(o) R(r) S(s) uv with R(r) = [[cos r, sin r], [-sin r, cos r]]. With gloss's
// v up (assimp flipped the meshes' v) the same map is (u, v) * s, turned counter-clockwise by r,
// plus (o.x + sin r s.y, 1 - o.y - cos r s.y) (docs/scene-format.md, "Maps from model files").
void transform_settings(const ModelTextureRef& ref, TextureMap& map) {
  if (!ref.transformed) return;
  const float sx = ref.scaling[0], sy = ref.scaling[1];
  const float r = -ref.rotation;
  const float c = std::cos(r), s = std::sin(r);
  const float ox = ref.translation[0] - 0.5f * sx * (1.0f - c + s);
  const float oy = 0.5f * sy * (s + c - 1.0f) + 1.0f - sy - ref.translation[1];
  map.scale = {sx, sy};
  map.rotation = r * 180.0f / kPi;
  map.offset = {ox + s * sy, 1.0f - oy - c * sy};
}

struct Source {
  const ModelTextureRef* ref = nullptr;
  TextureMap map;  // settings, file and texture
};

bool same_coordinates(const TextureMap& a, const TextureMap& b) {
  return a.uv_set == b.uv_set && a.scale == b.scale && a.rotation == b.rotation &&
         a.offset == b.offset && a.wrap == b.wrap;
}

glm::vec4 read(const TextureMap& map, float u, float v) {
  return bilinear(*map.texture, 0, u, v, map.wrap[0], map.wrap[1]);
}

}  // namespace

void read_gltf_maps(ModelMapReader& reader) {
  Model& model = reader.model;
  for (std::size_t m = 0; m < model.materials.size() && m < model.file_materials.size(); ++m) {
    const ModelFileMaterial& file = model.file_materials[m];
    const std::string& name = model.material_names[m];
    Material& material = model.materials[m];
    auto load = [&](const ModelTextureRef& ref, bool colour, MapSlot slot) {
      Source out;
      out.ref = &ref;
      TextureMap& map = out.map;
      map.wrap = {wrap_of(ref.wrap_u), wrap_of(ref.wrap_v)};
      map.uv_set = ref.uv_set;
      if (ref.uv_set > 1) {
        reader.unusable(name, "texture coordinate set " + std::to_string(ref.uv_set) +
                                  " (gloss reads sets 0 and 1); set 0 used");
        map.uv_set = 0;
      }
      transform_settings(ref, map);
      if (!ref.path.empty() && ref.path[0] == '*') {
        map.texture = reader.read_embedded(name, ref.path, colour);
        map.file = model_map_reference(reader.model_path, name, slot);
      } else {
        map.texture = reader.read_file(name, decode_uri(ref.path), colour, map.file);
      }
      return out;
    };
    Source base, mr, occlusion;
    for (const ModelTextureRef& ref : file.textures) {
      switch (ref.type) {
        case aiTextureType_DIFFUSE:
          base = load(ref, true, MapSlot::diffuse);
          if (base.map.present()) material.map(MapSlot::diffuse) = base.map;
          break;
        case aiTextureType_EMISSIVE:
        case aiTextureType_SPECULAR:
        case aiTextureType_AMBIENT: {
          const MapSlot slot = ref.type == aiTextureType_EMISSIVE   ? MapSlot::emission
                               : ref.type == aiTextureType_SPECULAR ? MapSlot::specular
                                                                    : MapSlot::ambient;
          Source s = load(ref, true, slot);
          if (s.map.present()) material.map(slot) = s.map;
          break;
        }
        case aiTextureType_NORMALS:
        case aiTextureType_HEIGHT:
        case aiTextureType_SHININESS:
        case aiTextureType_OPACITY: {
          const MapSlot slot = ref.type == aiTextureType_NORMALS     ? MapSlot::normal
                               : ref.type == aiTextureType_HEIGHT    ? MapSlot::bump
                               : ref.type == aiTextureType_SHININESS ? MapSlot::shininess
                                                                     : MapSlot::opacity;
          Source s = load(ref, false, slot);
          if (!s.map.present()) break;
          material.map(slot) = s.map;
          if (slot == MapSlot::normal) material.normal_scale = ref.strength;
          break;
        }
        case aiTextureType_LIGHTMAP:
          occlusion = load(ref, false, MapSlot::ambient);
          break;
        case aiTextureType_UNKNOWN:
          if (file.gltf) {
            mr = load(ref, false, MapSlot::specular);
            break;
          }
          [[fallthrough]];
        default:
          reader.unusable(name, "a texture of assimp type " + std::to_string(ref.type) + " (" +
                                    ref.path + "): no gloss map takes it");
      }
    }
    const bool with_base = base.map.present();

    // Metallic-roughness, per texel by the constants' rule (model_material.h), on the finer of
    // the two grids when the base colour shares its coordinates.
    if (mr.map.present()) {
      const bool shared = with_base && same_coordinates(base.map, mr.map);
      if (with_base && !shared) {
        reader.unusable(name,
                        "base colour and metallic-roughness textures use different "
                        "coordinates: the specular map uses the base colour factor");
      }
      const Texture& t = *mr.map.texture;
      const int w = shared ? std::max(t.width(), base.map.texture->width()) : t.width();
      const int h = shared ? std::max(t.height(), base.map.texture->height()) : t.height();
      const glm::vec3 factor(file.base_colour);
      auto params = [&](float u, float v, glm::vec3& colour, float& metal, float& rough) {
        const glm::vec4 texel = read(mr.map, u, v);
        colour = shared ? factor * glm::vec3(read(base.map, u, v)) : factor;
        metal = std::clamp(file.metallic * texel.b, 0.0f, 1.0f);
        rough = std::clamp(file.roughness * texel.g, 0.0f, 1.0f);
      };
      auto specular =
          reader.make(name, "specular map from metallic-roughness", w, h, 4, [&](float u, float v) {
            glm::vec3 colour;
            float metal, rough;
            params(u, v, colour, metal, rough);
            return glm::vec4(glm::mix(glm::vec3(0.04f), colour, metal) * (1.0f - rough), 1.0f);
          });
      auto shininess =
          reader.make(name, "shininess map from roughness", w, h, 1, [&](float u, float v) {
            glm::vec3 colour;
            float metal, rough;
            params(u, v, colour, metal, rough);
            return glm::vec4((1.0f - rough) * (1.0f - rough));
          });
      if (specular && shininess) {
        TextureMap s = mr.map, a = mr.map;
        s.texture = specular;
        s.file = model_map_reference(reader.model_path, name, MapSlot::specular);
        a.texture = shininess;
        a.file = model_map_reference(reader.model_path, name, MapSlot::shininess);
        material.map(MapSlot::specular) = s;
        material.map(MapSlot::shininess) = a;
        material.specular = glm::vec3(1.0f);
        material.shininess = 1000.0f;
      }
    }

    // Occlusion: the ambient map is the base colour times it (an ambient map replaces the
    // diffuse map's part in ka).
    if (occlusion.map.present()) {
      if (with_base && !same_coordinates(base.map, occlusion.map)) {
        reader.unusable(name,
                        "occlusion texture uses other coordinates than the base colour; "
                        "left out");
      } else {
        const Texture& t = *occlusion.map.texture;
        const int w = with_base ? std::max(t.width(), base.map.texture->width()) : t.width();
        const int h = with_base ? std::max(t.height(), base.map.texture->height()) : t.height();
        const float strength = occlusion.ref->strength;
        auto ambient = reader.make(
            name, "ambient map from occlusion", w, h, with_base ? 4 : 1, [&](float u, float v) {
              const float o = 1.0f + strength * (read(occlusion.map, u, v).r - 1.0f);
              const glm::vec4 b = with_base ? read(base.map, u, v) : glm::vec4(1.0f);
              return glm::vec4(glm::vec3(b) * o, 1.0f);
            });
        if (ambient) {
          TextureMap a = occlusion.map;
          a.texture = ambient;
          a.file = model_map_reference(reader.model_path, name, MapSlot::ambient);
          material.map(MapSlot::ambient) = a;
        }
      }
    }

    // Alpha: MASK is a cut-out at alpha_cutoff; gloss cuts at 0.5, so the opacity map is the
    // base colour's alpha times its factor, times 0.5 / cutoff. BLEND is drawn opaque.
    if (file.alpha_mode == "BLEND") {
      reader.unusable(name, "alpha mode BLEND (transparency): drawn opaque");
    } else if (file.alpha_mode == "MASK") {
      const float cutoff = file.alpha_cutoff > 0.0f ? file.alpha_cutoff : 1e-6f;
      const float factor = file.base_colour.a * 0.5f / cutoff;
      const bool as_is = with_base && base.map.texture->has_alpha && factor == 1.0f;
      if (as_is) {
        material.map(MapSlot::opacity) = base.map;  // its alpha, never sRGB-decoded
      } else {
        const int w = with_base ? base.map.texture->width() : 1;
        const int h = with_base ? base.map.texture->height() : 1;
        auto opacity = reader.make(name, "opacity map from alpha", w, h, 1, [&](float u, float v) {
          return glm::vec4((with_base ? read(base.map, u, v).a : 1.0f) * factor);
        });
        if (opacity) {
          TextureMap o = with_base ? base.map : TextureMap{};
          o.texture = opacity;
          o.file = model_map_reference(reader.model_path, name, MapSlot::opacity);
          material.map(MapSlot::opacity) = o;
        }
      }
    }
  }
}

}  // namespace gloss

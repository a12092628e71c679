#include "editor/model/export/glsl_export_maps.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "base/text/printable_text.h"
#include "editor/model/export/glsl_export.h"
#include "io/image/image_io.h"
#include "texture/texture_lookup.h"

namespace gloss {

namespace {

// Whether the slot's map is read from the image's alpha (an opacity map of an RGBA image): its
// level files then hold that alpha as grey.
bool reads_alpha(MapSlot slot, const TextureMap& map) {
  return slot == MapSlot::opacity && map.texture->has_alpha;
}

// `const TYPE NAME[8] = TYPE[8](...);`, entry(slot) giving each slot's literal.
template <class F>
std::string slot_array(const char* type, const char* name, F entry) {
  std::string s = std::string("const ") + type + " " + name + "[8] = " + type + "[8](";
  for (int i = 0; i < kMapSlots; ++i) s += (i ? ", " : "") + entry(static_cast<MapSlot>(i));
  return s + ");\n";
}

}  // namespace

std::string glsl_float(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
  std::string s = text;
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string map_level_name(const std::string& shader_path, MapSlot slot, int level) {
  return std::filesystem::path(shader_path).stem().string() + "-" + map_key(slot) + "-L" +
         std::to_string(level) + ".pfm";
}

std::string map_declarations(const Material& m, MapFilter filter, const std::string& shader_path) {
  if (!m.textured()) return "";
  std::string s;
  s += "// The material's maps (docs/spec/shading.md, \"Textures\"). The host supplies, per\n";
  s += "// fragment: gloss_uv0, gloss_uv1 (the hit's (u, v) of both sets, v up), gloss_tangent\n";
  s += "// (set 0's tangent, w its handedness +-1), gloss_uv_density (per set, the triangle's\n";
  s += "// sqrt((u, v) area / world area)), gloss_dpdu and gloss_dpdv (the triangle's dp/du and\n";
  s += "// dp/dv, for a bump map), and gloss_cone_spread = 2 tan(fov_y / 2) / image height.\n";
  s += "// Each map's sampler gets its levels from the files beside this shader, level k from\n";
  s +=
      "// STEM-SLOT_map-Lk.pfm (linear float RGB; PFM stores rows bottom to top: upload row 0 as\n";
  s += "// the image's top row, as GL_RGBA32F level k); texelFetch reads them, no GL filtering.\n";
  s +=
      "in vec2 gloss_uv0;\nin vec2 gloss_uv1;\nin vec4 gloss_tangent;\nin vec2 gloss_uv_density;\n";
  s += "in vec3 gloss_dpdu;\nin vec3 gloss_dpdv;\nuniform float gloss_cone_spread;\n";
  for (int i = 0; i < kMapSlots; ++i) {
    const auto slot = static_cast<MapSlot>(i);
    const TextureMap& map = m.map(slot);
    s += "uniform sampler2D gloss_map_" + std::string(to_string(slot)) + ";";
    if (map.present()) {
      s += "  // " + printable_text(map.file) + ": " + std::to_string(map.texture->level_count()) +
           " levels, " + map_level_name(shader_path, slot, 0) + " ...";
    } else {
      s += "  // none";
    }
    s += "\n";
  }
  s += slot_array("bool", "gloss_map_present",
                  [&](MapSlot slot) { return std::string(m.has_map(slot) ? "true" : "false"); });
  s += slot_array("ivec2", "gloss_map_wrap", [&](MapSlot slot) {
    const TextureMap& map = m.map(slot);
    return "ivec2(" + std::to_string(static_cast<int>(map.wrap[0])) + ", " +
           std::to_string(static_cast<int>(map.wrap[1])) + ")";
  });
  s += slot_array("vec4", "gloss_map_transform", [&](MapSlot slot) {
    const TextureMap& map = m.map(slot);
    const double angle = static_cast<double>(map.rotation) * (3.14159265358979323846 / 180.0);
    const float c = map.rotation == 0.0f ? 1.0f : static_cast<float>(std::cos(angle));
    const float n = map.rotation == 0.0f ? 0.0f : static_cast<float>(std::sin(angle));
    return "vec4(" + glsl_float(map.scale.x) + ", " + glsl_float(map.scale.y) + ", " +
           glsl_float(c) + ", " + glsl_float(n) + ")";
  });
  s += slot_array("vec2", "gloss_map_offset", [&](MapSlot slot) {
    const TextureMap& map = m.map(slot);
    return "vec2(" + glsl_float(map.offset.x) + ", " + glsl_float(map.offset.y) + ")";
  });
  s += slot_array("ivec2", "gloss_map_info", [&](MapSlot slot) {
    const TextureMap& map = m.map(slot);
    return "ivec2(" + std::to_string(map.uv_set == 1 ? 1 : 0) + ", " +
           std::to_string(map.present() ? map.texture->level_count() : 1) + ")";
  });
  // An opacity map's alpha is written as grey: the files have no alpha channel.
  s += slot_array("bool", "gloss_map_alpha", [](MapSlot) { return std::string("false"); });
  s += "const int gloss_map_filter = " + std::to_string(static_cast<int>(filter)) +
       ";  // render.map_filter \"" + to_string(filter) +
       "\" (0 trilinear, 1 bilinear, 2 nearest)\n";
  s += "const float gloss_normal_scale = " + glsl_float(m.normal_scale) + ";\n";
  s += "const float gloss_bump_scale = " + glsl_float(m.bump_scale) + ";\n\n";
  return s;
}

std::string map_lookup_part(const Material& m) {
  if (!m.textured()) return "";
  return std::string("// ---- shaders/texture_lookup.glsl ----\n") + kTextureLookupGlsl +
         "// ---- end of shaders/texture_lookup.glsl ----\n\n";
}

std::string map_main_body() {
  return "  vec3 n = normalize(gloss_normal);\n"
         "  vec3 v = normalize(gloss_eye - gloss_position);\n"
         "  float side = dot(n, v) < 0.0 ? -1.0 : 1.0;  // the two-sided rule\n"
         "  n *= side;\n"
         "  GlossMapFrame f;\n"
         "  f.uv[0] = gloss_uv0;\n"
         "  f.uv[1] = gloss_uv1;\n"
         "  // A cut-out: no surface where the opacity map is below 0.5.\n"
         "  if (gloss_map_present[GLOSS_MAP_OPACITY] &&\n"
         "      !gloss_opaque_at(gloss_map_opacity, GLOSS_MAP_OPACITY,\n"
         "                       f.uv[gloss_map_info[GLOSS_MAP_OPACITY].x])) {\n"
         "    discard;\n"
         "  }\n"
         "  float dist = length(gloss_position - gloss_eye);\n"
         "  f.footprint[0] = gloss_footprint(dist, dot(v, n), gloss_uv_density.x);\n"
         "  f.footprint[1] = gloss_footprint(dist, dot(v, n), gloss_uv_density.y);\n"
         "  f.n = n;\n"
         "  f.v = v;\n"
         "  f.side = side;\n"
         "  f.tangent = gloss_tangent.xyz;\n"
         "  f.handedness = gloss_tangent.w < 0.0 ? -1.0 : 1.0;\n"
         "  f.dpdu = gloss_dpdu;\n"
         "  f.dpdv = gloss_dpdv;\n"
         "  GlossMapValues m = gloss_map_values(f);\n"
         "  GlossTerms t = gloss_shade_at(gloss_position, n, m.n, v, gloss_ka * m.ka,\n"
         "                                gloss_kd * m.kd, gloss_ks * m.ks, gloss_ke * m.ke,\n"
         "                                gloss_alpha * m.alpha);\n";
}

std::vector<std::string> write_map_levels(const std::string& shader_path, const Material& m) {
  std::vector<std::string> written;
  const std::filesystem::path folder = std::filesystem::path(shader_path).parent_path();
  for (int i = 0; i < kMapSlots; ++i) {
    const auto slot = static_cast<MapSlot>(i);
    const TextureMap& map = m.map(slot);
    if (!map.present()) continue;
    const Texture& texture = *map.texture;
    const bool alpha = reads_alpha(slot, map);
    for (int l = 0; l < texture.level_count(); ++l) {
      const MipLevel& level = texture.levels[static_cast<std::size_t>(l)];
      Image image(level.width, level.height);
      for (std::size_t p = 0; p < image.pixels.size(); ++p) {
        const float* texel = level.texels.data() + p * static_cast<std::size_t>(texture.channels);
        if (texture.channels == 1) {
          image.pixels[p] = glm::vec3(texel[0]);
        } else {
          image.pixels[p] = alpha ? glm::vec3(texel[3]) : glm::vec3(texel[0], texel[1], texel[2]);
        }
      }
      const std::string path = (folder / map_level_name(shader_path, slot, l)).string();
      write_pfm(path, image);
      written.push_back(path);
    }
  }
  return written;
}

}  // namespace gloss

#include "editor/model/export/glsl_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <stdexcept>

#include "base/atomic_file.h"
#include "base/text/printable_text.h"
#include "editor/model/export/environment_atlas.h"
#include "editor/model/export/glsl_export_maps.h"
#include "io/image/image_io.h"
#include "shading/light_source.h"

namespace gloss {

namespace {

std::string literal(float value) {
  return glsl_float(value);
}

std::string vec3_literal(const glm::vec3& v) {
  return "vec3(" + literal(v.x) + ", " + literal(v.y) + ", " + literal(v.z) + ")";
}

// `const TYPE NAME[N] = TYPE[N](...);` with one entry per light, entry(light) its literal,
// and its source on each line.
std::string light_array(const Scene& scene, const char* type, const char* name, const char* field,
                        const std::function<std::string(const Light&)>& entry) {
  const std::string n = std::to_string(scene.lights.size());
  std::string out =
      std::string("const ") + type + " " + name + "[" + n + "] = " + type + "[" + n + "](\n";
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    out += "    " + entry(scene.lights[i]) + (i + 1 < scene.lights.size() ? "," : " ") +
           "  // lights[" + std::to_string(i) + "]." + field + "\n";
  }
  return out + ");\n";
}

std::string light_vec3_array(const Scene& scene, const char* name, const char* field,
                             glm::vec3 Light::*member) {
  return light_array(scene, "vec3", name, field,
                     [&](const Light& l) { return vec3_literal(l.*member); });
}

// 1 - cos(degrees) without the cancellation near 0: 2 sin^2(degrees / 2).
float one_minus_cos(double degrees) {
  const double half = std::sin(degrees * (3.14159265358979323846 / 360.0));
  return static_cast<float>(2.0 * half * half);
}

// The environment's part of the shader: its constants and environment.glsl, or a line saying
// there is none. atlas: the file the levels are written to, as the shader should name it.
std::string environment_part(const Scene& scene, const std::string& atlas) {
  if (!scene.environment.present()) {
    return "// The scene has no environment light.\n#define GLOSS_ENVIRONMENT 0\n\n";
  }
  PrefilterSettings settings;
  settings.texels_per_lobe = scene.render.env_resolution;
  const EnvironmentAtlas packed =
      make_environment_atlas(*prefiltered_environment(scene.environment.map, settings));
  const double a = scene.environment.rotation * (3.14159265358979323846 / 180.0);
  std::string s;
  s += "// The scene's environment light (" + printable_text(scene.environment.file) +
       "), its fast path: the map\n";
  s += "// prefiltered for Phong lobes of alpha 0, 1, 2 ... 1024 and the map itself, packed in\n";
  s += "// " + printable_text(atlas) + " beside this file (" + std::to_string(packed.image.width) +
       " x " + std::to_string(packed.image.height) +
       ", RGB float; PFM stores rows bottom to top: upload it with row 0\n";
  s += "// the image's top row, GL_RGB32F, and bind it to gloss_env_atlas). No horizon, no\n";
  s += "// shadows and, for Blinn-Phong, the Phong level of alpha / 4: docs/accuracy.md.\n";
  s += "#define GLOSS_ENVIRONMENT 1\n";
  s += "uniform sampler2D gloss_env_atlas;  // " + printable_text(atlas) + "\n";
  s += "const ivec4 gloss_env_level[13] = ivec4[13](\n";
  for (std::size_t k = 0; k < packed.levels.size(); ++k) {
    const glm::ivec4& l = packed.levels[k];
    s += "    ivec4(" + std::to_string(l.x) + ", " + std::to_string(l.y) + ", " +
         std::to_string(l.z) + ", " + std::to_string(l.w) + ")" +
         (k + 1 < packed.levels.size() ? "," : " ") +
         (k + 1 < packed.levels.size() ? "  // level " + std::to_string(k) : "  // the map") + "\n";
  }
  s += ");\n";
  s += "const vec2 gloss_env_rotation = vec2(" + literal(static_cast<float>(std::cos(a))) + ", " +
       literal(static_cast<float>(std::sin(a))) + ");  // environment.rotation " +
       literal(scene.environment.rotation) + " degrees\n";
  s += "const float gloss_env_intensity = " + literal(scene.environment.intensity) +
       ";  // environment.intensity\n";
  s += "// ---- shaders/environment.glsl ----\n";
  s += kEnvironmentGlsl;
  s += "// ---- end of shaders/environment.glsl ----\n\n";
  return s;
}

}  // namespace

std::string environment_atlas_name(const std::string& shader_path) {
  const std::filesystem::path p(shader_path);
  return p.stem().string() + "-environment.pfm";
}

std::string export_glsl(const Scene& scene, int material, const std::string& atlas,
                        const std::string& shader_path) {
  if (material < 0 || material >= static_cast<int>(scene.materials.size())) {
    throw std::out_of_range("no material " + std::to_string(material));
  }
  const Material& m = scene.materials[static_cast<std::size_t>(material)];
  // Names and paths come from files: a newline in one would end the GLSL comment it is in.
  const std::string name =
      printable_text(static_cast<std::size_t>(material) < scene.material_names.size()
                         ? scene.material_names[static_cast<std::size_t>(material)]
                         : "material " + std::to_string(material));
  const std::string where = "materials[" + std::to_string(material) + "] \"" + name + "\"";
  std::string s;
  s += "#version 330 core\n";
  s += "// For GLSL ES 3.00 / WebGL 2, make the line above `#version 300 es`; nothing else "
       "changes.\n";
  s += "// Exported by gloss (Export GLSL): the shading contract of docs/spec/shading.md for\n";
  s += "// " + where + " under the scene's " + std::to_string(scene.lights.size()) + " light(s)" +
       (scene.path.empty() ? "" : ", from " + printable_text(scene.path)) + ".\n";
  s += "//\n";
  s += "// The host program supplies, per fragment, in world space:\n";
  s += "//   gloss_position  the surface point p\n";
  s += "//   gloss_normal    the surface normal; used as both the shading normal n and the\n";
  s +=
      "//                   geometric normal n_g of the two-sided rule (pass the face normal for\n";
  s += "//                   flat meshes); normalised here\n";
  s += "//   gloss_eye       the camera position\n";
  s +=
      "// Outputs: location 0 the total; 1..4 the emissive, ambient, diffuse and specular terms.\n";
  s += "// Linear RGB, not clamped: use a float render target, or apply your display encoding.\n";
  s += "#ifdef GL_ES\nprecision highp float;\n#endif\n\n";
  s += "in vec3 gloss_position;\nin vec3 gloss_normal;\nuniform vec3 gloss_eye;\n";
  s += "layout(location = 0) out vec4 gloss_total;\n";
  s += "layout(location = 1) out vec4 gloss_emissive;\n";
  s += "layout(location = 2) out vec4 gloss_ambient;\n";
  s += "layout(location = 3) out vec4 gloss_diffuse;\n";
  s += "layout(location = 4) out vec4 gloss_specular;\n\n";
  s += "// The material: " + where +
       (m.preset.empty() ? "" : ", preset \"" + printable_text(m.preset) + "\"") + ".\n";
  s += "const vec3 gloss_ka = " + vec3_literal(m.ambient) + ";  // " + where + ".ambient\n";
  s += "const vec3 gloss_kd = " + vec3_literal(m.diffuse) + ";  // " + where + ".diffuse\n";
  s += "const vec3 gloss_ks = " + vec3_literal(m.specular) + ";  // " + where + ".specular\n";
  s += "const vec3 gloss_ke = " + vec3_literal(m.emission) + ";  // " + where + ".emission\n";
  s += "const float gloss_alpha = " + literal(m.shininess) + ";  // " + where + ".shininess\n\n";
  s += "// The scene and its render settings.\n";
  s += "const vec3 gloss_scene_ambient = " + vec3_literal(scene.ambient) + ";  // scene ambient\n";
  s += std::string("const int gloss_model = ") +
       (scene.render.model == ShadingModel::phong ? "0" : "1") + ";  // render.model \"" +
       to_string(scene.render.model) + "\" (0 GLOSS_PHONG, 1 GLOSS_BLINN_PHONG)\n";
  s += std::string("const bool gloss_energy_normalize = ") +
       (scene.render.energy_normalize ? "true" : "false") + ";  // render.energy_normalize\n\n";
  s += "// The lights, in the scene's order.\n";
  s += "#define GLOSS_LIGHT_COUNT " + std::to_string(scene.lights.size()) + "\n";
  if (!scene.lights.empty()) {
    s += light_vec3_array(scene, "gloss_light_position", "position", &Light::position);
    s += light_vec3_array(scene, "gloss_light_ambient", "ambient (La)", &Light::ambient);
    s += light_vec3_array(scene, "gloss_light_diffuse", "diffuse (Ld)", &Light::diffuse);
    s += light_vec3_array(scene, "gloss_light_specular", "specular (Ls)", &Light::specular);
    s += light_vec3_array(scene, "gloss_light_attenuation", "attenuation (c0, c1, c2)",
                          &Light::attenuation);
    bool headlight = false;
    for (const Light& l : scene.lights) {
      headlight |= l.type == LightType::directional && l.follow_camera;
    }
    if (headlight) {
      s += "// A light that follows the camera has its direction turned into the world frame of\n"
           "// the scene's camera (camera.eye, target, up); recompute it for another camera.\n";
    }
    s += light_array(scene, "vec3", "gloss_light_direction", "direction (unit, world space)",
                     [&](const Light& l) {
                       return vec3_literal(glm::vec3(world_light_direction(l, scene.camera)));
                     });
    s += light_array(scene, "vec4", "gloss_light_cone",
                     "type, 1 - cos(cutoff), 1 - cos(min(inner, cutoff)), exponent",
                     [&](const Light& l) {
                       return "vec4(" + literal(float(static_cast<int>(l.type))) + ", " +
                              literal(one_minus_cos(l.cutoff)) + ", " +
                              literal(one_minus_cos(std::min(l.inner, l.cutoff))) + ", " +
                              literal(l.exponent) + ")";
                     });
  }
  s += "\n// Visibility of light i from p: 1 lit, 0 shadowed.\n";
  s += scene.render.shadows
           ? "// The scene has shadows on (render.shadows); this shader has no shadow\n"
             "// test: replace the body with your shadow-map lookup.\n"
           : "// The scene has shadows off (render.shadows).\n";
  s += "float gloss_visibility(int light, vec3 p, vec3 n_g) {\n  return 1.0;\n}\n\n";
  s += environment_part(scene, atlas);
  s += map_declarations(m, scene.render.map_filter, shader_path);
  s += "// ---- shaders/phong_contract.glsl ----\n";
  s += kPhongContractGlsl;
  s += "// ---- end of shaders/phong_contract.glsl ----\n\n";
  s += map_lookup_part(m);
  s += "void main() {\n";
  if (m.textured()) {
    s += map_main_body();
  } else {
    s += "  vec3 n = normalize(gloss_normal);\n";
    s += "  GlossTerms t = gloss_shade(gloss_position, n, n, gloss_eye);\n";
  }
  s += "  gloss_total = vec4(t.total, 1.0);\n";
  s += "  gloss_emissive = vec4(t.emissive, 1.0);\n";
  s += "  gloss_ambient = vec4(t.ambient, 1.0);\n";
  s += "  gloss_diffuse = vec4(t.diffuse, 1.0);\n";
  s += "  gloss_specular = vec4(t.specular, 1.0);\n";
  s += "}\n";
  return s;
}

void write_glsl_export(const std::string& path, const Scene& scene, int material) {
  const std::string atlas = environment_atlas_name(path);
  if (scene.environment.present()) {
    PrefilterSettings settings;
    settings.texels_per_lobe = scene.render.env_resolution;
    write_pfm(
        (std::filesystem::path(path).parent_path() / atlas).string(),
        make_environment_atlas(*prefiltered_environment(scene.environment.map, settings)).image);
  }
  write_map_levels(path, scene.materials.at(static_cast<std::size_t>(material)));
  write_text_atomically(path, export_glsl(scene, material, atlas, path));
}

}  // namespace gloss

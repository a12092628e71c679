#include "editor/gl/raster/raster_programs.h"

#include <stdexcept>
#include <string>

#include "editor/gl/gl_program.h"
#include "editor/gl/shader_sources.h"
#include "editor/model/export/glsl_export.h"

namespace gloss {

namespace {

const char* pass_name(RasterPass pass) {
  switch (pass) {
    case RasterPass::shadow:
      return "shadow";
    case RasterPass::pixel:
      return "pixel";
    case RasterPass::vertex:
      return "vertex";
  }
  return "?";
}

std::string describe(const RasterVariant& v) {
  const char* shape = v.shape == RasterShape::mesh     ? "mesh"
                      : v.shape == RasterShape::sphere ? "sphere"
                                                       : "sky";
  return std::string(shape) + " " + pass_name(v.pass) + " pass, " + std::to_string(v.light_count) +
         " lights" + (v.shadows ? ", shadow maps" : "") + (v.environment ? ", environment" : "") +
         (v.maps ? ", maps" : "") + ", light types " + std::to_string(v.light_types) +
         ", shadow kinds " + std::to_string(v.shadow_kinds) +
         (v.model == 0 ? ", Phong" : ", Blinn-Phong") + (v.energy_normalize ? ", normalised" : "");
}

}  // namespace

std::string RasterPrograms::source(const RasterVariant& v, GLenum stage) {
  std::string text = "#version 330 core\n";
  text += "#define GLOSS_LIGHT_COUNT " + std::to_string(v.light_count) + "\n";
  text += std::string("#define GLOSS_SHADOWS ") + (v.shadows ? "1" : "0") + "\n";
  text +=
      std::string("#define GLOSS_PER_VERTEX ") + (v.pass == RasterPass::vertex ? "1" : "0") + "\n";
  text += std::string("#define GLOSS_ENVIRONMENT ") + (v.environment ? "1" : "0") + "\n";
  text += std::string("#define GLOSS_MAPS ") + (v.maps ? "1" : "0") + "\n";
  const auto flag = [&](const char* name, int mask, int bit) {
    text += std::string("#define ") + name + ((mask >> bit) & 1 ? " 1\n" : " 0\n");
  };
  flag("GLOSS_POINT_LIGHTS", v.light_types, 0);
  flag("GLOSS_DIRECTIONAL_LIGHTS", v.light_types, 1);
  flag("GLOSS_SPOT_LIGHTS", v.light_types, 2);
  flag("GLOSS_SHADOW_CUBE_MAPS", v.shadow_kinds, 0);
  flag("GLOSS_SHADOW_PERSPECTIVE_MAPS", v.shadow_kinds, 1);
  flag("GLOSS_SHADOW_ORTHOGRAPHIC_MAPS", v.shadow_kinds, 2);
  text += "#define GLOSS_MODEL " + std::to_string(v.model) + "\n";
  text += std::string("#define GLOSS_ENERGY_NORMALIZE ") + (v.energy_normalize ? "1" : "0") + "\n";
  if (v.pass == RasterPass::shadow) text += "#define GLOSS_SHADOW_PASS 1\n";
  text += kRasterCommonGlsl;
  text += kEnvironmentGlsl;
  text += kPhongContractGlsl;
  if (v.maps) text += kTextureLookupGlsl;
  const bool vertex = stage == GL_VERTEX_SHADER;
  switch (v.shape) {
    case RasterShape::mesh:
      text += vertex ? kRasterMeshVertexShader : kRasterMeshFragmentShader;
      break;
    case RasterShape::sphere:
      text += vertex ? kRasterSphereVertexShader : kRasterSphereFragmentShader;
      break;
    case RasterShape::sky:
      text += vertex ? kRasterSkyVertexShader : kRasterSkyFragmentShader;
      break;
  }
  return text;
}

RasterPrograms::~RasterPrograms() {
  for (const auto& [variant, program] : m_programs) glDeleteProgram(program);
}

GLuint RasterPrograms::get(const RasterVariant& variant) {
  const auto found = m_programs.find(variant);
  if (found != m_programs.end()) return found->second;
  const auto text = [&](GLenum stage) {
    return m_edit ? m_edit(source(variant, stage)) : source(variant, stage);
  };
  const GLuint program = build_program(text(GL_VERTEX_SHADER), text(GL_FRAGMENT_SHADER),
                                       "the raster program (" + describe(variant) + ")");
  m_programs.emplace(variant, program);
  return program;
}

void set_uniform(GLuint program, const char* name, int value) {
  glUniform1i(glGetUniformLocation(program, name), value);
}

void set_uniform(GLuint program, const char* name, float value) {
  glUniform1f(glGetUniformLocation(program, name), value);
}

void set_uniform(GLuint program, const char* name, float x, float y) {
  glUniform2f(glGetUniformLocation(program, name), x, y);
}

void set_uniform(GLuint program, const char* name, const float* xyz, int count) {
  glUniform3fv(glGetUniformLocation(program, name), count, xyz);
}

void set_uniform_vec2s(GLuint program, const char* name, const float* xy, int count) {
  glUniform2fv(glGetUniformLocation(program, name), count, xy);
}

void set_uniform_vec4s(GLuint program, const char* name, const float* xyzw, int count) {
  glUniform4fv(glGetUniformLocation(program, name), count, xyzw);
}

void set_uniform_ivec4s(GLuint program, const char* name, const int* xyzw, int count) {
  glUniform4iv(glGetUniformLocation(program, name), count, xyzw);
}

void set_uniform_ivec2s(GLuint program, const char* name, const int* xy, int count) {
  glUniform2iv(glGetUniformLocation(program, name), count, xy);
}

void set_uniform_ints(GLuint program, const char* name, const int* x, int count) {
  glUniform1iv(glGetUniformLocation(program, name), count, x);
}

}  // namespace gloss

#include "editor/gl/raster_programs.h"

#include <stdexcept>
#include <string>

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
  return std::string(v.shape == RasterShape::mesh ? "mesh" : "sphere") + " " + pass_name(v.pass) +
         " pass, " + std::to_string(v.light_count) + " lights" + (v.shadows ? ", shadow maps" : "");
}

GLuint compile(GLenum stage, const std::string& text, const RasterVariant& variant) {
  const GLuint shader = glCreateShader(stage);
  const char* source = text.c_str();
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error(std::string("cannot compile the raster ") +
                             (stage == GL_VERTEX_SHADER ? "vertex" : "fragment") + " shader (" +
                             describe(variant) + "): " + log);
  }
  return shader;
}

}  // namespace

std::string RasterPrograms::source(const RasterVariant& v, GLenum stage) {
  std::string text = "#version 330 core\n";
  text += "#define GLOSS_LIGHT_COUNT " + std::to_string(v.light_count) + "\n";
  text += std::string("#define GLOSS_SHADOWS ") + (v.shadows ? "1" : "0") + "\n";
  text +=
      std::string("#define GLOSS_PER_VERTEX ") + (v.pass == RasterPass::vertex ? "1" : "0") + "\n";
  if (v.pass == RasterPass::shadow) text += "#define GLOSS_SHADOW_PASS 1\n";
  text += kRasterCommonGlsl;
  text += kPhongContractGlsl;
  const bool mesh = v.shape == RasterShape::mesh;
  if (stage == GL_VERTEX_SHADER) {
    text += mesh ? kRasterMeshVertexShader : kRasterSphereVertexShader;
  } else {
    text += mesh ? kRasterMeshFragmentShader : kRasterSphereFragmentShader;
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
  const GLuint vertex = compile(GL_VERTEX_SHADER, text(GL_VERTEX_SHADER), variant);
  GLuint fragment = 0;
  try {
    fragment = compile(GL_FRAGMENT_SHADER, text(GL_FRAGMENT_SHADER), variant);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint linked = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  if (!linked) {
    char log[4096] = {};
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    glDeleteProgram(program);
    throw std::runtime_error("cannot link the raster program (" + describe(variant) + "): " + log);
  }
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

}  // namespace gloss

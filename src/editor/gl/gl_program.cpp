#include "editor/gl/gl_program.h"

#include <stdexcept>

namespace gloss {

GLuint compile_shader(GLenum stage, const std::string& text, const std::string& what) {
  const GLuint shader = glCreateShader(stage);
  const char* source = text.c_str();
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[4096] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error("cannot compile the " +
                             std::string(stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                             " shader of " + what + ": " + log);
  }
  return shader;
}

GLuint build_program(const std::string& vertex_text, const std::string& fragment_text,
                     const std::string& what) {
  const GLuint vertex = compile_shader(GL_VERTEX_SHADER, vertex_text, what);
  GLuint fragment = 0;
  try {
    fragment = compile_shader(GL_FRAGMENT_SHADER, fragment_text, what);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);  // flagged; freed with the program
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[4096] = {};
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    glDeleteProgram(program);
    throw std::runtime_error("cannot link " + what + ": " + log);
  }
  return program;
}

}  // namespace gloss

#include "editor/gl/display_shader.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "editor/gl/gl_program.h"
#include "editor/gl/shader_sources.h"
#include "editor/model/view/heat_map.h"

namespace gloss {

DisplayShader::DisplayShader() {
  m_program = build_program(kDisplayVertexShader, kDisplayFragmentShader,
                            "the display shaders (display.vert, display.frag)");
  m_a = glGetUniformLocation(m_program, "u_a");
  m_b = glGetUniformLocation(m_program, "u_b");
  m_mode = glGetUniformLocation(m_program, "u_mode");
  m_gain = glGetUniformLocation(m_program, "u_gain");
  m_tone = glGetUniformLocation(m_program, "u_tone");
  m_srgb = glGetUniformLocation(m_program, "u_srgb");
  m_heat_scale = glGetUniformLocation(m_program, "u_heat_scale");
  m_heat_ramp = glGetUniformLocation(m_program, "u_heat_ramp");
  m_clip_overlay = glGetUniformLocation(m_program, "u_clip_overlay");
  glGenVertexArrays(1, &m_vertex_array);
}

DisplayShader::~DisplayShader() {
  if (m_vertex_array != 0) glDeleteVertexArrays(1, &m_vertex_array);
  if (m_program != 0) glDeleteProgram(m_program);
}

void DisplayShader::draw(GLuint texture_a, GLuint texture_b, const DisplayParams& params) const {
  glUseProgram(m_program);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture_a);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, texture_b != 0 ? texture_b : texture_a);
  glUniform1i(m_a, 0);
  glUniform1i(m_b, 1);
  glUniform1i(m_mode, static_cast<GLint>(params.mode));
  glUniform1f(m_gain, params.display.gain);
  glUniform1i(m_tone, static_cast<GLint>(params.display.tone));
  glUniform1i(m_srgb, params.display.srgb ? 1 : 0);
  glUniform1f(m_heat_scale, std::max(params.heat_scale, 1e-6f));
  glUniform1i(m_clip_overlay, params.clip_overlay ? 1 : 0);
  glUniform3fv(m_heat_ramp, kHeatRampSize, &kHeatRamp[0].x);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(m_vertex_array);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glActiveTexture(GL_TEXTURE0);
  glUseProgram(0);
}

}  // namespace gloss

#pragma once
// The viewport's display transform as a GL program built from shaders/display.{vert,frag}:
// draws one pane (the current GL viewport) from one or two linear float textures. The shader is
// display/display_transform.h's GLSL twin; the GL tests hold it to that function.
#include <glad/gl.h>

#include "display/display_transform.h"

namespace gloss {

// image: texture a; sum: a + b (emissive + ambient); heat: the heat ramp of max |a - b|.
enum class DisplayMode { image = 0, sum = 1, heat = 2 };

struct DisplayParams {
  DisplayMode mode = DisplayMode::image;
  DisplayTransform display;   // the document's (render.exposure, render.tone, render.srgb)
  float heat_scale = 0.1f;    // linear difference at the ramp's top; values <= 0 use 1e-6
  bool clip_overlay = false;  // stripes over pixels with a channel above 1 before the clamp
};

class DisplayShader {
 public:
  // Compiles and links; throws std::runtime_error with the GL info log on failure.
  DisplayShader();
  ~DisplayShader();
  DisplayShader(const DisplayShader&) = delete;
  DisplayShader& operator=(const DisplayShader&) = delete;

  // Draws into the current framebuffer and viewport. b may be 0 for DisplayMode::image.
  void draw(GLuint texture_a, GLuint texture_b, const DisplayParams& params) const;

 private:
  GLuint m_program = 0;
  GLuint m_vertex_array = 0;  // empty: the vertex shader makes its triangle from gl_VertexID
  GLint m_mode = -1, m_gain = -1, m_tone = -1, m_srgb = -1, m_heat_scale = -1, m_heat_ramp = -1;
  GLint m_clip_overlay = -1;
  GLint m_a = -1, m_b = -1;
};

}  // namespace gloss

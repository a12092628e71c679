#pragma once
// A GL texture holding one linear float image (GL_RGB32F) or 8-bit display colours (GL_RGB8).
// Needs a current GL 3.3 context with glad loaded. Move-only; deletes its texture.
#include <glad/gl.h>

#include "base/image.h"

namespace gloss {

class GlTexture {
 public:
  GlTexture() = default;
  ~GlTexture();
  GlTexture(GlTexture&& other) noexcept;
  GlTexture& operator=(GlTexture&& other) noexcept;
  GlTexture(const GlTexture&) = delete;
  GlTexture& operator=(const GlTexture&) = delete;

  // Uploads image (row 0 = top, stored as texture row 0). Reallocates only when the size
  // changes. Linear filtering, clamped edges.
  void upload(const Image& image);
  // Nearest sampling (true) or linear. Nearest is exact when texels map 1:1 to pixels, and
  // llvmpipe samples float textures about 4x cheaper with it (one fetch instead of four).
  void set_nearest(bool nearest);
  // Uploads width * height * 3 bytes of 8-bit RGB (swatches).
  void upload_rgb8(int width, int height, const unsigned char* rgb);

  GLuint id() const { return m_id; }
  int width() const { return m_width; }
  int height() const { return m_height; }
  bool empty() const { return m_id == 0 || m_width == 0; }

 private:
  void prepare(int width, int height, GLint internal_format);

  GLuint m_id = 0;
  int m_width = 0, m_height = 0;
  GLint m_format = 0;
  bool m_nearest = false;
};

}  // namespace gloss

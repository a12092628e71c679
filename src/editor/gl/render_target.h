#pragma once
// An off-screen framebuffer with one RGBA8 colour texture: the viewport draws its panes here and
// ImGui shows the texture; the EGL tests read it back.
#include <vector>

#include <glad/gl.h>

namespace gloss {

class RenderTarget {
 public:
  RenderTarget() = default;
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  // (Re)allocates the colour texture when the size changes. Throws std::runtime_error when the
  // framebuffer is incomplete.
  void resize(int width, int height);
  // Binds the framebuffer and sets the GL viewport to all of it.
  void bind() const;
  static void unbind();

  // Copies the whole target into the default framebuffer with its lower left corner at (x, y)
  // in GL window coordinates (rows from the bottom). A blit is a plain copy in llvmpipe, far
  // cheaper than drawing the texture as a blended, textured quad.
  void blit_to_window(int x, int y) const;

  // Rows bottom to top, as glReadPixels returns them: width * height * 4 bytes.
  std::vector<unsigned char> read_rgba() const;

  GLuint texture() const { return m_texture; }
  int width() const { return m_width; }
  int height() const { return m_height; }

 private:
  GLuint m_framebuffer = 0;
  GLuint m_texture = 0;
  int m_width = 0, m_height = 0;
};

}  // namespace gloss

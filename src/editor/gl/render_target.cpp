#include "editor/gl/render_target.h"

#include <stdexcept>
#include <string>

namespace gloss {

RenderTarget::~RenderTarget() {
  if (m_texture != 0) glDeleteTextures(1, &m_texture);
  if (m_framebuffer != 0) glDeleteFramebuffers(1, &m_framebuffer);
}

void RenderTarget::resize(int width, int height) {
  if (width == m_width && height == m_height && m_framebuffer != 0) return;
  if (width <= 0 || height <= 0) throw std::runtime_error("render target size must be positive");
  if (m_framebuffer == 0) glGenFramebuffers(1, &m_framebuffer);
  if (m_texture == 0) glGenTextures(1, &m_texture);
  glBindTexture(GL_TEXTURE_2D, m_texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  // Shown pixel for pixel: nearest sampling is exact and cheaper in software GL.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_texture, 0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("framebuffer incomplete (status " + std::to_string(status) + ")");
  }
  m_width = width;
  m_height = height;
}

void RenderTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer);
  glViewport(0, 0, m_width, m_height);
}

void RenderTarget::unbind() {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void RenderTarget::blit_to_window(int x, int y) const {
  if (m_framebuffer == 0) return;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, m_framebuffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, m_width, m_height, x, y, x + m_width, y + m_height, GL_COLOR_BUFFER_BIT,
                    GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::vector<unsigned char> RenderTarget::read_rgba() const {
  std::vector<unsigned char> pixels(static_cast<std::size_t>(m_width) * m_height * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, m_framebuffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, m_width, m_height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return pixels;
}

}  // namespace gloss

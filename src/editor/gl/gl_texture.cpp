#include "editor/gl/gl_texture.h"

#include <utility>

namespace gloss {

GlTexture::~GlTexture() {
  if (m_id != 0) glDeleteTextures(1, &m_id);
}

GlTexture::GlTexture(GlTexture&& other) noexcept
    : m_id(std::exchange(other.m_id, 0)),
      m_width(std::exchange(other.m_width, 0)),
      m_height(std::exchange(other.m_height, 0)),
      m_format(std::exchange(other.m_format, 0)),
      m_nearest(std::exchange(other.m_nearest, false)) {}

GlTexture& GlTexture::operator=(GlTexture&& other) noexcept {
  if (this != &other) {
    if (m_id != 0) glDeleteTextures(1, &m_id);
    m_id = std::exchange(other.m_id, 0);
    m_width = std::exchange(other.m_width, 0);
    m_height = std::exchange(other.m_height, 0);
    m_format = std::exchange(other.m_format, 0);
    m_nearest = std::exchange(other.m_nearest, false);
  }
  return *this;
}

void GlTexture::prepare(int width, int height, GLint internal_format) {
  if (m_id == 0) {
    glGenTextures(1, &m_id);
    glBindTexture(GL_TEXTURE_2D, m_id);
    const GLint filter = m_nearest ? GL_NEAREST : GL_LINEAR;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  } else {
    glBindTexture(GL_TEXTURE_2D, m_id);
  }
  // Rows are tightly packed (3 floats or 3 bytes per pixel).
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (width != m_width || height != m_height || internal_format != m_format) {
    const GLenum type = internal_format == GL_RGB32F ? GL_FLOAT : GL_UNSIGNED_BYTE;
    glTexImage2D(GL_TEXTURE_2D, 0, internal_format, width, height, 0, GL_RGB, type, nullptr);
    m_width = width;
    m_height = height;
    m_format = internal_format;
  }
}

void GlTexture::set_nearest(bool nearest) {
  if (nearest == m_nearest) return;
  m_nearest = nearest;
  if (m_id == 0) return;  // prepare() applies it
  const GLint filter = nearest ? GL_NEAREST : GL_LINEAR;
  glBindTexture(GL_TEXTURE_2D, m_id);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
}

void GlTexture::upload(const Image& image) {
  if (image.width <= 0 || image.height <= 0) return;
  prepare(image.width, image.height, GL_RGB32F);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGB, GL_FLOAT,
                  image.pixels.data());
}

void GlTexture::upload_rgb8(int width, int height, const unsigned char* rgb) {
  if (width <= 0 || height <= 0) return;
  prepare(width, height, GL_RGB8);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb);
}

}  // namespace gloss

#include "editor/gl/shadow_maps.h"

#include <limits>

namespace gloss {

ShadowMaps::~ShadowMaps() {
  if (m_framebuffer != 0) glDeleteFramebuffers(1, &m_framebuffer);
  if (m_texture != 0) glDeleteTextures(1, &m_texture);
}

bool ShadowMaps::update(const Scene& scene, int size,
                        const std::function<void(const RasterView&)>& draw) {
  std::vector<float> numbers;
  std::vector<const void*> meshes;
  for (const PointLight& l : scene.lights) {
    numbers.insert(numbers.end(), {l.position.x, l.position.y, l.position.z});
  }
  for (const Object& o : scene.objects) {
    if (o.type == ObjectType::sphere) {
      numbers.insert(numbers.end(), {o.center.x, o.center.y, o.center.z, o.radius});
    } else {
      meshes.push_back(o.mesh.get());
    }
  }
  const int layers = 6 * static_cast<int>(scene.lights.size());
  if (numbers == m_key_numbers && meshes == m_key_meshes && size == m_size && layers == m_layers &&
      m_texture != 0) {
    return false;
  }
  m_key_numbers = std::move(numbers);
  m_key_meshes = std::move(meshes);

  if (m_texture == 0 || size != m_size || layers != m_layers) {
    if (m_texture == 0) glGenTextures(1, &m_texture);
    glBindTexture(GL_TEXTURE_2D_ARRAY, m_texture);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_R32F, size, size, layers, 0, GL_RED, GL_FLOAT, nullptr);
    // texelFetch only; the filters still have to name a complete texture.
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    m_size = size;
    m_layers = layers;
  }
  if (m_framebuffer == 0) glGenFramebuffers(1, &m_framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendEquation(GL_MIN);
  glViewport(0, 0, size, size);
  const float nothing[4] = {std::numeric_limits<float>::max(), 0.0f, 0.0f, 0.0f};
  for (int layer = 0; layer < layers; ++layer) {
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, m_texture, 0, layer);
    const GLenum target = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &target);
    glClearBufferfv(GL_COLOR, 0, nothing);
    draw(cube_face_view(scene.lights[static_cast<std::size_t>(layer / 6)].position, layer % 6));
  }
  glBlendEquation(GL_FUNC_ADD);
  glDisable(GL_BLEND);
  return true;
}

std::size_t ShadowMaps::bytes() const {
  return static_cast<std::size_t>(m_size) * m_size * m_layers * sizeof(float);
}

}  // namespace gloss

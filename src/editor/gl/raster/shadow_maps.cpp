#include "editor/gl/raster/shadow_maps.h"

#include <limits>
#include <stdexcept>
#include <string>

#include "shading/light_source.h"

namespace gloss {

ShadowMaps::~ShadowMaps() {
  if (m_framebuffer != 0) glDeleteFramebuffers(1, &m_framebuffer);
  if (m_texture != 0) glDeleteTextures(1, &m_texture);
}

namespace {
// Each light's kind of map, its layers and view, in scene order.
std::vector<LightShadow> plan_shadows(const Scene& scene, const std::vector<DrawnBox>& boxes,
                                      int& layers) {
  std::vector<LightShadow> out;
  layers = 0;
  for (const Light& light : scene.lights) {
    const LightSource<float> source = make_light_source<float>(light, scene.camera);
    LightShadow shadow;
    shadow.first_layer = layers;
    if (light.type == LightType::directional) {
      shadow.kind = LightShadow::orthographic;
      shadow.view = directional_view(source.direction, boxes);
    } else if (light.type == LightType::spot && light.cutoff <= kMaxSpotMapCutoff) {
      shadow.kind = LightShadow::perspective;
      shadow.view = spot_view(light.position, source.direction, light.cutoff);
    }
    layers += shadow.kind == LightShadow::cube ? 6 : 1;
    out.push_back(shadow);
  }
  return out;
}

void add_view(const RasterView& v, std::vector<float>& numbers) {
  numbers.insert(numbers.end(), {v.origin.x, v.origin.y, v.origin.z, v.forward.x, v.forward.y,
                                 v.forward.z, v.scale.x, v.scale.y});
}
}  // namespace

bool ShadowMaps::update(const Scene& scene, const std::vector<DrawnBox>& boxes, int size,
                        const std::function<void(const RasterView&)>& draw) {
  int layers = 0;
  std::vector<LightShadow> planned = plan_shadows(scene, boxes, layers);
  std::vector<float> numbers;
  std::vector<const void*> meshes;
  for (std::size_t i = 0; i < planned.size(); ++i) {
    const glm::vec3& p = scene.lights[i].position;
    numbers.insert(numbers.end(), {float(planned[i].kind), p.x, p.y, p.z});
    if (planned[i].kind != LightShadow::cube) add_view(planned[i].view, numbers);
  }
  for (const Object& o : scene.objects) {
    if (o.hidden) {
      meshes.push_back(nullptr);  // hiding or showing an object redraws the maps
    } else if (o.type == ObjectType::sphere) {
      numbers.insert(numbers.end(), {o.center.x, o.center.y, o.center.z, o.radius});
    } else {
      meshes.push_back(o.mesh.get());
    }
  }
  if (numbers == m_key_numbers && meshes == m_key_meshes && size == m_size && layers == m_layers &&
      m_texture != 0) {
    return false;
  }
  // The key is kept only once the maps are drawn: a throw below leaves them marked stale.
  m_key_numbers.clear();
  m_key_meshes.clear();
  m_lights = std::move(planned);

  if (m_texture == 0 || size != m_size || layers != m_layers) {
    const double bytes = double(size) * size * layers * sizeof(float);
    if (bytes > double(kMaxShadowMapBytes)) {
      throw std::runtime_error("shadow maps for " + std::to_string(m_lights.size()) +
                               " lights at " + std::to_string(size) + " texels would take " +
                               std::to_string(static_cast<long long>(bytes / (1 << 20))) +
                               " MiB, more than the raster path's " +
                               std::to_string(kMaxShadowMapBytes >> 20) +
                               " MiB; choose a smaller shadow map");
    }
    if (m_texture == 0) glGenTextures(1, &m_texture);
    glBindTexture(GL_TEXTURE_2D_ARRAY, m_texture);
    for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {
    }
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_R32F, size, size, layers, 0, GL_RED, GL_FLOAT, nullptr);
    if (glGetError() != GL_NO_ERROR) {  // out of memory, most likely
      m_size = m_layers = 0;
      throw std::runtime_error("cannot allocate the shadow maps (" +
                               std::to_string(m_lights.size()) + " lights at " +
                               std::to_string(size) + " texels)");
    }
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
  auto draw_layer = [&](int layer, const RasterView& view) {
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, m_texture, 0, layer);
    const GLenum target = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &target);
    glClearBufferfv(GL_COLOR, 0, nothing);
    draw(view);
  };
  for (std::size_t i = 0; i < m_lights.size(); ++i) {
    const LightShadow& l = m_lights[i];
    if (l.kind != LightShadow::cube) {
      draw_layer(l.first_layer, l.view);
      continue;
    }
    for (int face = 0; face < 6; ++face) {
      draw_layer(l.first_layer + face, cube_face_view(scene.lights[i].position, face));
    }
  }
  glBlendEquation(GL_FUNC_ADD);
  glDisable(GL_BLEND);
  m_key_numbers = std::move(numbers);
  m_key_meshes = std::move(meshes);
  return true;
}

std::size_t ShadowMaps::bytes() const {
  return static_cast<std::size_t>(m_size) * m_size * m_layers * sizeof(float);
}

}  // namespace gloss

#include "engine/shade/recombination.h"

#include "shading/shading.h"

namespace gloss {

Recombination::Recombination(const RenderContext& ctx)
    : m_lights(ctx.plan.lights.size()),
      m_stride(6 + 6 * ctx.plan.lights.size()),
      m_background(ctx.scene->background) {
  const Scene& scene = *ctx.scene;
  glm::vec3 ambient_light = scene.ambient;
  for (const PointLight& light : scene.lights) ambient_light += light.ambient;
  m_flat.reserve(scene.materials.size() * m_stride);
  for (const Material& mat : scene.materials) {
    const glm::vec3 ambient = mat.ambient * ambient_light;
    for (int c = 0; c < 3; ++c) m_flat.push_back(mat.emission[c]);
    for (int c = 0; c < 3; ++c) m_flat.push_back(ambient[c]);
    const float norm = scene.render.energy_normalize
                           ? energy_normalization(scene.render.model, mat.shininess)
                           : 1.0f;
    for (int index : ctx.plan.lights) {
      const PointLight& light = scene.lights[static_cast<std::size_t>(index)];
      const glm::vec3 kd_ld = mat.diffuse * light.diffuse;
      const glm::vec3 ks_ls = mat.specular * norm * light.specular;
      for (int c = 0; c < 3; ++c) m_flat.push_back(kd_ld[c]);
      for (int c = 0; c < 3; ++c) m_flat.push_back(ks_ls[c]);
    }
  }
  m_materials = scene.materials.size();
  m_columns.resize(m_flat.size());
  for (std::size_t m = 0; m < m_materials; ++m) {
    for (std::size_t j = 0; j < m_stride; ++j) {
      m_columns[j * m_materials + m] = m_flat[m * m_stride + j];
    }
  }
}

}  // namespace gloss

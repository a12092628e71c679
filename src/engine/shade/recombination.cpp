#include "engine/shade/recombination.h"

#include "shading/shading.h"

namespace gloss {

Recombination::Recombination(const RenderContext& ctx)
    : m_lights(ctx.plan.slots()),
      m_stride(6 + 6 * ctx.plan.slots()),
      m_background(ctx.scene->background) {
  const Scene& scene = *ctx.scene;
  glm::vec3 ambient_light = scene.ambient;
  for (const Light& light : scene.lights) ambient_light += light.ambient;
  m_flat.reserve(scene.materials.size() * m_stride);
  for (const Material& mat : scene.materials) {
    const glm::vec3 ambient = mat.ambient * ambient_light;
    for (int c = 0; c < 3; ++c) m_flat.push_back(mat.emission[c]);
    for (int c = 0; c < 3; ++c) m_flat.push_back(ambient[c]);
    const float norm = scene.render.energy_normalize
                           ? energy_normalization(scene.render.model, mat.shininess)
                           : 1.0f;
    for (int index : ctx.plan.lights) {
      const Light& light = scene.lights[static_cast<std::size_t>(index)];
      const glm::vec3 kd_ld = mat.diffuse * light.diffuse;
      const glm::vec3 ks_ls = mat.specular * norm * light.specular;
      for (int c = 0; c < 3; ++c) m_flat.push_back(kd_ld[c]);
      for (int c = 0; c < 3; ++c) m_flat.push_back(ks_ls[c]);
    }
    // The environment's slot of channel k carries that channel's terms at intensity 1 (its
    // diffuse and specular weights are radiance): kd and ks in channel k only, times the
    // intensity. The energy normalisation does not apply to it (its lobe is normalised).
    if (ctx.plan.environment) {
      const float intensity = scene.environment.intensity;
      for (int k = 0; k < 3; ++k) {
        for (int c = 0; c < 3; ++c) m_flat.push_back(c == k ? mat.diffuse[c] * intensity : 0.0f);
        for (int c = 0; c < 3; ++c) m_flat.push_back(c == k ? mat.specular[c] * intensity : 0.0f);
      }
    }
  }
  m_sky_shown = ctx.plan.sky && scene.environment.as_background;
  m_sky_intensity = scene.environment.intensity;
  m_materials = scene.materials.size();
  m_columns.resize(m_flat.size());
  for (std::size_t m = 0; m < m_materials; ++m) {
    for (std::size_t j = 0; j < m_stride; ++j) {
      m_columns[j * m_materials + m] = m_flat[m * m_stride + j];
    }
  }
}

}  // namespace gloss

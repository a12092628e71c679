#include "editor/gl/raster/environment_texture.h"

#include <cmath>

#include "editor/gl/raster/raster_programs.h"
#include "editor/model/export/environment_atlas.h"

namespace gloss {

void EnvironmentTexture::update(const Scene& scene) {
  PrefilterSettings settings;
  settings.texels_per_lobe = scene.render.env_resolution;
  std::shared_ptr<const PrefilteredEnvironment> maps =
      prefiltered_environment(scene.environment.map, settings);
  if (maps == m_maps && !m_texture.empty()) return;
  const EnvironmentAtlas atlas = make_environment_atlas(*maps);
  m_texture.set_nearest(true);  // texelFetch only; the filter must still name a complete texture
  m_texture.upload(atlas.image);
  m_levels = atlas.levels;
  m_maps = std::move(maps);
}

void EnvironmentTexture::use(GLuint program, const Scene& scene, int unit) const {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(GL_TEXTURE_2D, m_texture.id());
  glActiveTexture(GL_TEXTURE0);
  set_uniform(program, "gloss_env_atlas", unit);
  std::vector<int> levels;
  for (const glm::ivec4& l : m_levels) levels.insert(levels.end(), {l.x, l.y, l.z, l.w});
  set_uniform_ivec4s(program, "gloss_env_level", levels.data(), static_cast<int>(m_levels.size()));
  const double a = scene.environment.rotation * (3.14159265358979323846 / 180.0);
  set_uniform(program, "gloss_env_rotation", static_cast<float>(std::cos(a)),
              static_cast<float>(std::sin(a)));
  set_uniform(program, "gloss_env_intensity", scene.environment.intensity);
}

std::size_t EnvironmentTexture::bytes() const {
  return static_cast<std::size_t>(m_texture.width()) * m_texture.height() * 12;
}

}  // namespace gloss

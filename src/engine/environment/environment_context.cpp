#include "engine/environment/environment_context.h"

namespace gloss {

namespace {
bool nonzero(const glm::vec3& c) {
  return c.x != 0.0f || c.y != 0.0f || c.z != 0.0f;
}
}  // namespace

EnvironmentContext make_environment_context(const Scene& scene, bool planned) {
  EnvironmentContext e;
  if (!planned || !scene.environment.present()) return e;
  PrefilterSettings settings;
  settings.texels_per_lobe = scene.render.env_resolution;
  e.maps = prefiltered_environment(scene.environment.map, settings);
  if (scene.render.env_samples > 0) e.sampler = environment_sampler(scene.environment.map);
  e.rotation = environment_rotation<float>(scene.environment.rotation);
  e.rotation_d = environment_rotation<double>(scene.environment.rotation);
  for (const Material& m : scene.materials) {
    e.exponent.push_back(phong_equivalent_exponent(scene.render.model, m.shininess));
    e.diffuse.push_back(nonzero(m.diffuse) ? 1 : 0);
    e.specular.push_back(nonzero(m.specular) ? 1 : 0);
  }
  if (e.exponent.empty()) {
    e.exponent.push_back(0.0f);
    e.diffuse.push_back(0);
    e.specular.push_back(0);
  }
  for (const Object& o : scene.objects) e.object_material.push_back(o.material);
  return e;
}

}  // namespace gloss

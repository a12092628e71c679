#include "editor/gl/raster/raster_uniforms.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "editor/gl/raster/raster_programs.h"
#include "shading/light_source.h"

namespace gloss {

namespace {
// 1 - cos(degrees), without the cancellation of 1 - cos near 0: 2 sin^2(degrees / 2).
float one_minus_cos(double degrees) {
  const double half = std::sin(degrees * (3.14159265358979323846 / 360.0));
  return static_cast<float>(2.0 * half * half);
}
}  // namespace

void set_material_uniforms(GLuint program, const Material& m) {
  set_uniform(program, "gloss_ka", &m.ambient.x);
  set_uniform(program, "gloss_kd", &m.diffuse.x);
  set_uniform(program, "gloss_ks", &m.specular.x);
  set_uniform(program, "gloss_ke", &m.emission.x);
  set_uniform(program, "gloss_alpha", m.shininess);
}

void set_scene_uniforms(GLuint program, const Scene& scene) {
  set_uniform(program, "gloss_scene_ambient", &scene.ambient.x);
  const int n = static_cast<int>(scene.lights.size());
  if (n == 0) return;
  std::vector<float> position, ambient, diffuse, specular, attenuation, direction, cone;
  for (const Light& l : scene.lights) {
    const glm::vec3 d = make_light_source<float>(l, scene.camera).direction;  // world, unit
    position.insert(position.end(), {l.position.x, l.position.y, l.position.z});
    ambient.insert(ambient.end(), {l.ambient.x, l.ambient.y, l.ambient.z});
    diffuse.insert(diffuse.end(), {l.diffuse.x, l.diffuse.y, l.diffuse.z});
    specular.insert(specular.end(), {l.specular.x, l.specular.y, l.specular.z});
    attenuation.insert(attenuation.end(), {l.attenuation.x, l.attenuation.y, l.attenuation.z});
    direction.insert(direction.end(), {d.x, d.y, d.z});
    cone.insert(cone.end(), {float(static_cast<int>(l.type)), one_minus_cos(l.cutoff),
                             one_minus_cos(std::min(l.inner, l.cutoff)), l.exponent});
  }
  set_uniform(program, "gloss_light_position", position.data(), n);
  set_uniform(program, "gloss_light_ambient", ambient.data(), n);
  set_uniform(program, "gloss_light_diffuse", diffuse.data(), n);
  set_uniform(program, "gloss_light_specular", specular.data(), n);
  set_uniform(program, "gloss_light_attenuation", attenuation.data(), n);
  set_uniform(program, "gloss_light_direction", direction.data(), n);
  set_uniform_vec4s(program, "gloss_light_cone", cone.data(), n);
}

void set_shadow_uniforms(GLuint program, const std::vector<LightShadow>& lights) {
  const int n = static_cast<int>(lights.size());
  std::vector<int> layout;
  std::vector<float> origin, forward, right, up, scale;
  for (const LightShadow& l : lights) {
    layout.insert(layout.end(), {l.first_layer, static_cast<int>(l.kind)});
    const RasterView& v = l.view;
    origin.insert(origin.end(), {v.origin.x, v.origin.y, v.origin.z});
    forward.insert(forward.end(), {v.forward.x, v.forward.y, v.forward.z});
    right.insert(right.end(), {v.right.x, v.right.y, v.right.z});
    up.insert(up.end(), {v.up.x, v.up.y, v.up.z});
    scale.insert(scale.end(), {v.scale.x, v.scale.y});
  }
  set_uniform_ivec2s(program, "gloss_shadow_layout", layout.data(), n);
  set_uniform(program, "gloss_shadow_origin", origin.data(), n);
  set_uniform(program, "gloss_shadow_forward", forward.data(), n);
  set_uniform(program, "gloss_shadow_right", right.data(), n);
  set_uniform(program, "gloss_shadow_up", up.data(), n);
  set_uniform_vec2s(program, "gloss_shadow_scale", scale.data(), n);
}

}  // namespace gloss

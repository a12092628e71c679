#include "editor/model/view/light_gizmo.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "editor/model/view/camera_controller.h"
#include "shading/light_source.h"

namespace gloss {

LightGizmo light_gizmo(const Light& light, const Camera& camera) {
  LightGizmo g;
  g.positioned = light.type != LightType::directional;
  g.aimed = light.type != LightType::point;
  g.position = light.position;
  if (!g.aimed) return g;
  g.direction = glm::vec3(world_light_direction(light, camera));
  const float view_distance = glm::length(camera.target - camera.eye);
  if (light.type == LightType::directional) {
    g.length = 0.35f * view_distance;
    g.handle = camera.target - g.direction * g.length;
    return g;
  }
  // A spot's cone reaches half way to the target, but stays visible when the light sits on it.
  g.length = std::max(0.5f * glm::length(camera.target - light.position), 0.1f * view_distance);
  g.handle = light.position + g.direction * g.length;
  const float drawn = std::min(light.cutoff, 80.0f) * (3.14159265f / 180.0f);
  g.cone_radius = g.length * std::tan(drawn);
  return g;
}

glm::vec3 direction_for_handle(const Light& light, const Camera& camera, const glm::vec3& p) {
  const glm::vec3 from =
      light.type == LightType::directional ? camera.target - p : p - light.position;
  const float len = glm::length(from);
  if (!(len > 0.0f) || !std::isfinite(len)) return light.direction;
  glm::vec3 d = from / len;
  if (light.type == LightType::directional && light.follow_camera) {
    const CameraBasis<double> frame = make_camera_basis<double>(camera, 1, 1);
    const glm::dvec3 w(d);
    d = glm::vec3(glm::dot(w, frame.right), glm::dot(w, frame.up), -glm::dot(w, frame.forward));
  }
  return d;
}

Light orbited_light(const Light& light, const glm::vec3& centre, float degrees) {
  Light out = light;
  if (light.type == LightType::directional && light.follow_camera) return out;
  if (light.type != LightType::directional) {
    out.position =
        rotate_about_y(light.position, glm::vec3(centre.x, light.position.y, centre.z), degrees);
  }
  if (light.type != LightType::point) {
    out.direction = rotate_about_y(light.direction, glm::vec3(0.0f), degrees);
  }
  return out;
}

}  // namespace gloss

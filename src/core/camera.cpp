#include "camera.h"

#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace gloss {

Camera orbit_camera(const Camera& camera, float yaw_deg, float pitch_deg) {
  const glm::vec3 offset = camera.eye - camera.target;
  const float radius = glm::length(offset);
  if (!(radius > 0.0f)) return camera;
  const glm::vec3 up = glm::normalize(camera.up);
  // Spherical angles of the eye around the target, measured against the camera's up axis.
  const glm::vec3 dir = offset / radius;
  glm::vec3 ref = std::abs(up.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 axis_a = glm::normalize(glm::cross(up, ref));
  const glm::vec3 axis_b = glm::cross(axis_a, up);
  float elevation = std::asin(glm::clamp(glm::dot(dir, up), -1.0f, 1.0f));
  float azimuth = std::atan2(glm::dot(dir, axis_b), glm::dot(dir, axis_a));
  azimuth += glm::radians(yaw_deg);
  // Stop just short of the poles so up never becomes parallel to the view direction.
  const float limit = glm::radians(89.0f);
  elevation = glm::clamp(elevation + glm::radians(pitch_deg), -limit, limit);
  const glm::vec3 new_dir =
      std::cos(elevation) * (std::cos(azimuth) * axis_a + std::sin(azimuth) * axis_b) +
      std::sin(elevation) * up;
  Camera out = camera;
  out.eye = camera.target + radius * new_dir;
  return out;
}

}  // namespace gloss

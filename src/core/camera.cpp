#include "camera.h"

#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace gloss {

CameraFrame make_camera_frame(const Camera& camera, int width, int height) {
  const glm::vec3 view = camera.target - camera.eye;
  const float view_len = glm::length(view);
  if (!(view_len > 0.0f) || !std::isfinite(view_len)) {
    throw std::invalid_argument("eye and target coincide");
  }
  CameraFrame frame;
  frame.eye = camera.eye;
  frame.forward = view / view_len;
  const glm::vec3 side = glm::cross(frame.forward, camera.up);
  const float side_len = glm::length(side);
  // Relative test: up must not be (anti)parallel to the view direction.
  if (!(side_len > 1e-6f * glm::length(camera.up))) {
    throw std::invalid_argument("up is parallel to the view direction");
  }
  frame.right = side / side_len;
  frame.up = glm::cross(frame.right, frame.forward);
  const float tan_half = std::tan(glm::radians(camera.fov_y) * 0.5f);
  frame.scale_y = tan_half;
  frame.scale_x = tan_half * static_cast<float>(width) / static_cast<float>(height);
  return frame;
}

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

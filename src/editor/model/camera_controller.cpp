#include "editor/model/camera_controller.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace gloss {

Camera pan_camera(const Camera& camera, float dx_px, float dy_px, int view_height) {
  const CameraFrame frame =
      make_camera_frame(camera, std::max(view_height, 1), std::max(view_height, 1));
  const float distance = glm::length(camera.target - camera.eye);
  // World units per pixel at the target's depth: the view is 2 tan(fov/2) d tall.
  const float per_px =
      2.0f * frame.scale_y * distance / static_cast<float>(std::max(view_height, 1));
  const glm::vec3 shift = (-dx_px * frame.right + dy_px * frame.up) * per_px;
  Camera out = camera;
  out.eye += shift;
  out.target += shift;
  return out;
}

Camera zoom_camera(const Camera& camera, float steps) {
  const glm::vec3 offset = camera.eye - camera.target;
  const float distance = glm::length(offset);
  const float next = std::max(distance * std::pow(kZoomPerStep, steps), kMinViewDistance);
  Camera out = camera;
  out.eye = camera.target + offset * (next / distance);
  return out;
}

bool project_point(const Camera& camera, int width, int height, const glm::vec3& p,
                   glm::vec2& image_position) {
  const CameraFrame frame = make_camera_frame(camera, width, height);
  const glm::vec3 d = p - frame.eye;
  const float z = glm::dot(d, frame.forward);
  if (!(z > 1e-6f)) return false;
  const float sx = glm::dot(d, frame.right) / z;
  const float sy = glm::dot(d, frame.up) / z;
  // Inverse of the spec's sx = (2 px / W - 1) scale_x, sy = (1 - 2 py / H) scale_y.
  image_position.x = (sx / frame.scale_x + 1.0f) * 0.5f * static_cast<float>(width);
  image_position.y = (1.0f - sy / frame.scale_y) * 0.5f * static_cast<float>(height);
  return true;
}

glm::vec3 point_at_depth(const Camera& camera, int width, int height, const glm::vec2& px,
                         const glm::vec3& anchor) {
  const CameraFrame frame = make_camera_frame(camera, width, height);
  const glm::vec3 direction = primary_direction(frame, px.x, px.y, width, height);
  const float depth = glm::dot(anchor - frame.eye, frame.forward);
  const float along = glm::dot(direction, frame.forward);
  if (!(depth > 0.0f) || !(along > 0.0f)) return anchor;
  return frame.eye + direction * (depth / along);
}

glm::vec3 rotate_about_y(const glm::vec3& p, const glm::vec3& centre, float degrees) {
  const float a = glm::radians(degrees);
  const float c = std::cos(a), s = std::sin(a);
  const glm::vec3 d = p - centre;
  return centre + glm::vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
}

}  // namespace gloss

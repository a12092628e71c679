#include "scene/camera.h"

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

template <class T>
CameraBasis<T> make_camera_basis(const Camera& camera, int width, int height) {
  using V = glm::tvec3<T>;
  const V view = V(camera.target) - V(camera.eye);
  const T view_len = glm::length(view);
  if (!(view_len > T(0)) || !std::isfinite(view_len)) {
    throw std::invalid_argument("eye and target coincide");
  }
  CameraBasis<T> basis;
  basis.eye = V(camera.eye);
  basis.forward = view / view_len;
  const V side = glm::cross(basis.forward, V(camera.up));
  const T side_len = glm::length(side);
  // Relative test: up must not be (anti)parallel to the view direction.
  if (!(side_len > T(1e-6) * glm::length(V(camera.up)))) {
    throw std::invalid_argument("up is parallel to the view direction");
  }
  basis.right = side / side_len;
  basis.up = glm::cross(basis.right, basis.forward);
  const T tan_half = std::tan(T(camera.fov_y) * T(3.14159265358979323846) / T(360));
  basis.scale_y = tan_half;
  basis.scale_x = tan_half * T(width) / T(height);
  return basis;
}

template CameraBasis<float> make_camera_basis<float>(const Camera&, int, int);
template CameraBasis<double> make_camera_basis<double>(const Camera&, int, int);

}  // namespace gloss

#pragma once
// Pinhole camera of spec/shading.md: y up, right-handed, vertical field of view in degrees.
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace gloss {

struct Camera {
  glm::vec3 eye{0.0f, 0.0f, 5.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y = 40.0f;  // degrees, 0 < fov_y < 180
};

inline bool operator==(const Camera& a, const Camera& b) {
  return a.eye == b.eye && a.target == b.target && a.up == b.up && a.fov_y == b.fov_y;
}
inline bool operator!=(const Camera& a, const Camera& b) {
  return !(a == b);
}

// The orthonormal frame and image-plane scale derived from a Camera for a W x H image, in a
// scalar type T: float for Embree's rays, double where the renderer rebuilds hit points and for
// the reference path.
template <class T>
struct CameraBasis {
  glm::tvec3<T> eye, forward, right, up;  // f, r, u of the spec; unit length
  T scale_x = 1, scale_y = 1;             // tan(fov_y / 2) * W / H and tan(fov_y / 2)
};
using CameraFrame = CameraBasis<float>;

// Throws std::invalid_argument for eye == target or up parallel to the view direction.
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

inline CameraFrame make_camera_frame(const Camera& camera, int width, int height) {
  return make_camera_basis<float>(camera, width, height);
}

// Unit direction of the primary ray through image position (px, py) in pixels, where
// (x + 0.5, y + 0.5) is the centre of pixel (x, y), y growing downwards.
template <class T>
glm::tvec3<T> camera_direction(const CameraBasis<T>& basis, T px, T py, int width, int height) {
  const T sx = (px * (T(2) / T(width)) - T(1)) * basis.scale_x;  // 2 / W: hoisted out of loops
  const T sy = (T(1) - py * (T(2) / T(height))) * basis.scale_y;
  const glm::tvec3<T> d = basis.forward + sx * basis.right + sy * basis.up;
  return d * (T(1) / std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z));  // one division, not three
}

inline glm::vec3 primary_direction(const CameraFrame& frame, float px, float py, int width,
                                   int height) {
  return camera_direction<float>(frame, px, py, width, height);
}

// Orbits the eye around the target by yaw (about up) and pitch (about right), degrees.
Camera orbit_camera(const Camera& camera, float yaw_deg, float pitch_deg);

}  // namespace gloss

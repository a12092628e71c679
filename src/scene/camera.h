#pragma once
// Pinhole camera of docs/spec/shading.md: y up, right-handed, vertical field of view in degrees.
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

// Equal in every field of its table (scene/fields/fields.h).
bool operator==(const Camera& a, const Camera& b);
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

// Throws std::invalid_argument for eye == target or up parallel to the view direction. Defined
// in camera.cpp for float and double, so every target calls the one copy compiled with the
// pixel code's flags (src/CMakeLists.txt): an inline copy compiled for another instruction set
// would round differently.
template <class T>
CameraBasis<T> make_camera_basis(const Camera& camera, int width, int height);
extern template CameraBasis<float> make_camera_basis<float>(const Camera&, int, int);
extern template CameraBasis<double> make_camera_basis<double>(const Camera&, int, int);

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

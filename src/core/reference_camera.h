#pragma once
// The camera formula of spec/shading.md (camera.h) evaluated in a scalar type T, for the
// reference path: the float camera rounds the frame and every ray direction to float, which is
// part of what the reference measures.
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "camera.h"

namespace gloss {

template <class T>
struct ReferenceCamera {
  glm::tvec3<T> eye, forward, right, up;  // f, r, u of the spec; unit length
  T scale_x = 1, scale_y = 1;             // tan(fov_y / 2) * W / H and tan(fov_y / 2)
};

// The camera must be valid (validate_scene checks eye != target and up not along the view).
template <class T>
ReferenceCamera<T> make_reference_camera(const Camera& camera, int width, int height) {
  ReferenceCamera<T> c;
  c.eye = glm::tvec3<T>(camera.eye);
  c.forward = glm::normalize(glm::tvec3<T>(camera.target) - c.eye);
  c.right = glm::normalize(glm::cross(c.forward, glm::tvec3<T>(camera.up)));
  c.up = glm::cross(c.right, c.forward);
  const T pi = T(3.14159265358979323846);
  const T tan_half = std::tan(T(camera.fov_y) * pi / T(360));
  c.scale_y = tan_half;
  c.scale_x = tan_half * T(width) / T(height);
  return c;
}

// Unit direction through image position (px, py) in pixels, (x + 0.5, y + 0.5) the centre of
// pixel (x, y), y growing downwards.
template <class T>
glm::tvec3<T> reference_direction(const ReferenceCamera<T>& c, T px, T py, int width, int height) {
  const T sx = (T(2) * px / T(width) - T(1)) * c.scale_x;
  const T sy = (T(1) - T(2) * py / T(height)) * c.scale_y;
  return glm::normalize(c.forward + sx * c.right + sy * c.up);
}

}  // namespace gloss

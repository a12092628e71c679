#pragma once
// Pinhole camera of spec/shading.md: y up, right-handed, vertical field of view in degrees.
#include <cmath>

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

// The orthonormal frame and image-plane scale derived from a Camera for a W x H image.
struct CameraFrame {
  glm::vec3 eye, forward, right, up;  // f, r, u of the spec; unit length
  float scale_x = 1, scale_y = 1;     // tan(fov_y / 2) * W / H and tan(fov_y / 2)
};

// Throws std::invalid_argument for eye == target or up parallel to the view direction.
CameraFrame make_camera_frame(const Camera& camera, int width, int height);

// Unit direction of the primary ray through image position (px, py) in pixels, where
// (x + 0.5, y + 0.5) is the centre of pixel (x, y), y growing downwards. Inline: the renderer
// evaluates it for 16 lanes at a time.
inline glm::vec3 primary_direction(const CameraFrame& frame, float px, float py, int width,
                                   int height) {
  const float sx = (2.0f * px / static_cast<float>(width) - 1.0f) * frame.scale_x;
  const float sy = (1.0f - 2.0f * py / static_cast<float>(height)) * frame.scale_y;
  const glm::vec3 d = frame.forward + sx * frame.right + sy * frame.up;
  return d / std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

// Orbits the eye around the target by yaw (about up) and pitch (about right), degrees.
Camera orbit_camera(const Camera& camera, float yaw_deg, float pitch_deg);

}  // namespace gloss

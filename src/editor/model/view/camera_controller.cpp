#include "editor/model/view/camera_controller.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "scene/geometry/mesh.h"

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

Camera overscan_camera(const Camera& camera, float document_aspect, float pane_aspect) {
  if (!(pane_aspect > 0.0f) || !(pane_aspect < document_aspect)) return camera;
  // The horizontal field, tan(fov_y / 2) x aspect, stays the document's.
  const double half = std::tan(glm::radians(static_cast<double>(camera.fov_y)) * 0.5);
  const double wider = half * static_cast<double>(document_aspect) / pane_aspect;
  Camera out = camera;
  // Below 180 degrees, as every camera's field of view (a float could round up to it).
  out.fov_y = std::min(static_cast<float>(glm::degrees(2.0 * std::atan(wider))), 179.5f);
  return out;
}

glm::vec3 new_light_position(const Camera& camera, int width, int height) {
  const glm::vec3 anchor = camera.eye + 0.5f * (camera.target - camera.eye);
  const glm::vec2 px(0.7f * static_cast<float>(width), 0.25f * static_cast<float>(height));
  return point_at_depth(camera, width, height, px, anchor);
}

EdgeMarker edge_marker(const Camera& camera, int width, int height, const glm::vec3& p,
                       float margin, float top_margin) {
  EdgeMarker m;
  const float w = static_cast<float>(width), h = static_cast<float>(height);
  glm::vec2 at;
  if (project_point(camera, width, height, p, at) && at.x >= 0.0f && at.y >= 0.0f && at.x < w &&
      at.y < h) {
    m.position = at;
    m.on_screen = true;
    return m;
  }
  // The direction of p seen from the eye, in image axes (x right, y down). Behind the eye the
  // view-plane components still say which side it is on.
  const CameraFrame frame = make_camera_frame(camera, width, height);
  const glm::vec3 d = p - frame.eye;
  glm::vec2 dir(glm::dot(d, frame.right) / frame.scale_x * 0.5f * w,
                -glm::dot(d, frame.up) / frame.scale_y * 0.5f * h);
  if (glm::length(dir) < 1e-9f) dir = glm::vec2(0.0f, -1.0f);  // straight behind: say "up"
  dir = glm::normalize(dir);
  const glm::vec2 centre(0.5f * w, 0.5f * h);
  const float top = top_margin >= 0.0f ? top_margin : margin;
  const glm::vec2 half(std::max(0.5f * w - margin, 0.0f),
                       std::max(0.5f * h - (dir.y < 0.0f ? top : margin), 0.0f));
  // Scale the direction to the inset rectangle's border.
  const float tx = std::abs(dir.x) > 1e-9f ? half.x / std::abs(dir.x) : 1e30f;
  const float ty = std::abs(dir.y) > 1e-9f ? half.y / std::abs(dir.y) : 1e30f;
  m.position = centre + dir * std::min(tx, ty);
  m.direction = dir;
  return m;
}

bool screen_bounds(const Camera& camera, int width, int height, const Object& object, glm::vec2& lo,
                   glm::vec2& hi) {
  glm::vec3 box_lo, box_hi;
  if (object.type == ObjectType::sphere) {
    box_lo = object.center - glm::vec3(object.radius);
    box_hi = object.center + glm::vec3(object.radius);
  } else if (!object.mesh || !mesh_bounds(*object.mesh, box_lo, box_hi)) {
    return false;
  }
  lo = glm::vec2(1e30f);
  hi = glm::vec2(-1e30f);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? box_hi.x : box_lo.x, (corner & 2) ? box_hi.y : box_lo.y,
                      (corner & 4) ? box_hi.z : box_lo.z);
    glm::vec2 at;
    if (!project_point(camera, width, height, p, at)) return false;
    lo = glm::min(lo, at);
    hi = glm::max(hi, at);
  }
  return true;
}

Camera frame_camera(const Camera& camera, const glm::vec3& lo, const glm::vec3& hi, float aspect) {
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float radius = 0.5f * glm::length(hi - lo);
  glm::vec3 back = camera.eye - camera.target;
  const float length = glm::length(back);
  back = length > 0.0f ? back / length : glm::vec3(0, 0, 1);
  // Half the narrower field of view: tan(h / 2) = tan(v / 2) x aspect horizontally.
  const float tan_v = std::tan(glm::radians(0.5f * camera.fov_y));
  const float half = std::atan(tan_v * std::min(1.0f, std::max(aspect, 1e-3f)));
  const float distance = radius > 0.0f ? 1.1f * radius / std::sin(half) : length;
  Camera out = camera;
  out.target = centre;
  out.eye = centre + back * std::max(distance, kMinViewDistance);
  return out;
}

glm::vec3 rotate_about_y(const glm::vec3& p, const glm::vec3& centre, float degrees) {
  const float a = glm::radians(degrees);
  const float c = std::cos(a), s = std::sin(a);
  const glm::vec3 d = p - centre;
  return centre + glm::vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
}

}  // namespace gloss

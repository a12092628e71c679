#include "editor/gl/raster/raster_view.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "editor/gl/raster/raster_programs.h"

namespace gloss {

namespace {

// (A, B) for near and far planes at w = near and w = far (the usual perspective depth).
glm::vec2 depth_mapping(float near_w, float far_w) {
  return {(far_w + near_w) / (far_w - near_w), -2.0f * far_w * near_w / (far_w - near_w)};
}

// Distance from p to the box, 0 inside it.
float box_distance(const glm::vec3& p, const DrawnBox& b) {
  return glm::length(glm::max(glm::max(b.lo - p, p - b.hi), glm::vec3(0.0f)));
}

// The smallest and largest w of the box's corners (and so of the box).
glm::vec2 box_w_range(const RasterView& v, const DrawnBox& b) {
  glm::vec2 range(INFINITY, -INFINITY);
  for (int c = 0; c < 8; ++c) {
    const glm::vec3 corner((c & 1) ? b.hi.x : b.lo.x, (c & 2) ? b.hi.y : b.lo.y,
                           (c & 4) ? b.hi.z : b.lo.z);
    const float w = glm::dot(corner - v.origin, v.forward);
    range = {std::min(range.x, w), std::max(range.y, w)};
  }
  return range;
}

// cos of the widest angle between forward and a direction inside the frustum (its corners):
// a point at distance d from the origin inside the frustum has w >= d times this.
float widest_cosine(const RasterView& v) {
  return 1.0f / std::sqrt(1.0f + v.scale.x * v.scale.x + v.scale.y * v.scale.y);
}

}  // namespace

std::vector<DrawnBox> drawn_boxes(const Scene& scene) {
  std::vector<DrawnBox> boxes;
  for (const Object& o : scene.objects) {
    DrawnBox b;  // a hidden object's stays empty: it is not drawn, in no view, into no map
    if (o.hidden) {
    } else if (o.type == ObjectType::sphere) {
      b = {o.center - glm::vec3(1.01f * o.radius), o.center + glm::vec3(1.01f * o.radius), false};
    } else if (o.mesh) {
      b.empty = !mesh_bounds(*o.mesh, b.lo, b.hi);
    }
    boxes.push_back(b);
  }
  return boxes;
}

RasterView camera_view(const Scene& scene, const std::vector<DrawnBox>& boxes, int width,
                       int height) {
  const CameraFrame basis = make_camera_frame(scene.camera, width, height);
  RasterView v;
  v.origin = basis.eye;
  v.forward = basis.forward;
  v.right = basis.right;
  v.up = basis.up;
  v.scale = {basis.scale_x, basis.scale_y};
  // Far: the largest w of any box corner, 1 % beyond. Near: 1 % before the smallest w a visible
  // surface point can have. Two lower bounds for each object, the larger taken: the smallest w
  // of its box's corners (w is linear, so a box's extremes are at corners) or, for a sphere, of
  // its surface (dot(c - eye, f) - r); and its distance from the eye times the frustum's widest
  // cosine (a floor reaching behind the eye is still as far below it as it is).
  float far_w = 1e-3f, nearest = INFINITY;
  const float cosine = widest_cosine(v);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const DrawnBox& b = boxes[i];
    if (b.empty) continue;
    far_w = std::max(far_w, 1.01f * box_w_range(v, b).y);
    const Object& o = scene.objects[i];
    float lowest = 0.0f;
    if (o.type == ObjectType::sphere) {
      lowest = std::max(glm::dot(o.center - v.origin, v.forward) - o.radius,
                        (glm::length(o.center - v.origin) - o.radius) * cosine);
    } else {
      lowest = std::max(box_w_range(v, b).x, box_distance(v.origin, b) * cosine);
    }
    nearest = std::min(nearest, lowest);
  }
  v.near_w = std::max(0.99f * nearest, 1e-6f * far_w);
  if (!(v.near_w < far_w)) v.near_w = 1e-6f * far_w;  // nothing in front of the eye
  v.depth = depth_mapping(v.near_w, far_w);
  return v;
}

RasterView cube_face_view(const glm::vec3& light_position, int face) {
  // The frames of raster_common.glsl's gloss_cube_face, face by face.
  const float s = (face % 2 == 0) ? 1.0f : -1.0f;
  RasterView v;
  v.origin = light_position;
  if (face < 2) {
    v.forward = {s, 0.0f, 0.0f};
    v.right = {0.0f, 0.0f, -s};
    v.up = {0.0f, 1.0f, 0.0f};
  } else if (face < 4) {
    v.forward = {0.0f, s, 0.0f};
    v.right = {1.0f, 0.0f, 0.0f};
    v.up = {0.0f, 0.0f, -s};
  } else {
    v.forward = {0.0f, 0.0f, s};
    v.right = {s, 0.0f, 0.0f};
    v.up = {0.0f, 1.0f, 0.0f};
  }
  v.scale = {1.0f, 1.0f};
  // Infinite far plane: z / w = 1 - 2 near / w stays below 1 for every w >= near. near is tiny
  // (1e-6 of the light's distance from the origin, at least 1e-6) so that nothing near the light
  // is clipped away.
  v.near_w = std::max(1e-6f, 1e-6f * glm::length(light_position));
  v.depth = {1.0f, -2.0f * v.near_w};
  return v;
}

namespace {
// Two unit vectors completing unit forward to a frame (right, up): up is the world's y unless
// forward is nearly along it. right = cross(forward, up) keeps the camera's handedness.
void frame_across(const glm::vec3& forward, glm::vec3& right, glm::vec3& up) {
  const glm::vec3 hint = std::abs(forward.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  right = glm::normalize(glm::cross(forward, hint));
  up = glm::cross(right, forward);
}
}  // namespace

RasterView spot_view(const glm::vec3& position, const glm::vec3& direction, float cutoff_degrees) {
  RasterView v;
  v.origin = position;
  v.forward = direction;
  frame_across(direction, v.right, v.up);
  const float spread = std::tan(cutoff_degrees * 3.14159265f / 180.0f);
  v.scale = {spread, spread};
  v.near_w = std::max(1e-6f, 1e-6f * glm::length(position));
  v.depth = {1.0f, -2.0f * v.near_w};
  return v;
}

RasterView directional_view(const glm::vec3& direction, const std::vector<DrawnBox>& boxes) {
  RasterView v;
  v.orthographic = true;
  v.forward = direction;
  frame_across(direction, v.right, v.up);
  glm::vec3 lo(INFINITY), hi(-INFINITY);  // along right, up, forward
  for (const DrawnBox& b : boxes) {
    if (b.empty) continue;
    for (int c = 0; c < 8; ++c) {
      const glm::vec3 corner((c & 1) ? b.hi.x : b.lo.x, (c & 2) ? b.hi.y : b.lo.y,
                             (c & 4) ? b.hi.z : b.lo.z);
      const glm::vec3 k(glm::dot(corner, v.right), glm::dot(corner, v.up),
                        glm::dot(corner, v.forward));
      lo = glm::min(lo, k);
      hi = glm::max(hi, k);
    }
  }
  if (!(lo.x <= hi.x)) lo = glm::vec3(-1.0f), hi = glm::vec3(1.0f);
  // 1 % of the extent around it (at least 1e-6 of its size), so no silhouette is shaved off.
  const glm::vec3 margin = glm::max(0.01f * (hi - lo), glm::vec3(1e-6f * glm::length(hi - lo)));
  lo -= margin;
  hi += margin;
  const glm::vec3 centre = 0.5f * (lo + hi);
  v.origin = centre.x * v.right + centre.y * v.up + lo.z * v.forward;
  v.scale = {0.5f * (hi.x - lo.x), 0.5f * (hi.y - lo.y)};
  const float depth = hi.z - lo.z;
  v.near_w = 0.0f;
  v.depth = {2.0f / depth, -1.0f};  // w = 0 .. depth to -1 .. 1
  return v;
}

bool may_be_seen(const RasterView& view, const DrawnBox& box) {
  if (box.empty) return false;
  const glm::vec3 centre = 0.5f * (box.lo + box.hi);
  const float radius = 0.5f * glm::length(box.hi - box.lo);
  if (view.orthographic) {  // every box is inside the box the view was fitted to
    return true;
  }
  // In front of the origin and inside the four side planes, |dot(d, right)| <= scale.x
  // dot(d, forward) and the same with up, for the box's bounding sphere.
  const glm::vec3 d = centre - view.origin;
  if (glm::dot(d, view.forward) < -radius) return false;
  const glm::vec3 planes[4] = {
      view.scale.x * view.forward - view.right, view.scale.x * view.forward + view.right,
      view.scale.y * view.forward - view.up, view.scale.y * view.forward + view.up};
  for (const glm::vec3& n : planes) {
    if (glm::dot(d, n) < -radius * glm::length(n)) return false;
  }
  return true;
}

bool near_faces_suffice(const RasterView& view, const DrawnBox& cube) {
  if (view.orthographic) return false;  // both faces: parallel rays have no eye to face
  // Outside the cube and every corner (so every point) of it past the near plane.
  return box_distance(view.origin, cube) > 0.0f && box_w_range(view, cube).x > view.near_w;
}

void set_view_uniforms(GLuint program, const RasterView& view) {
  set_uniform(program, "gloss_view_origin", &view.origin.x);
  set_uniform(program, "gloss_view_forward", &view.forward.x);
  set_uniform(program, "gloss_view_right", &view.right.x);
  set_uniform(program, "gloss_view_up", &view.up.x);
  set_uniform(program, "gloss_view_scale", view.scale.x, view.scale.y);
  set_uniform(program, "gloss_view_depth", view.depth.x, view.depth.y);
  set_uniform(program, "gloss_view_ortho", view.orthographic ? 1 : 0);
}

}  // namespace gloss

#include "editor/gl/raster_view.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "editor/gl/raster_programs.h"

namespace gloss {

namespace {

// (A, B) for near and far planes at w = near and w = far (the usual perspective depth).
glm::vec2 depth_mapping(float near_w, float far_w) {
  return {(far_w + near_w) / (far_w - near_w), -2.0f * far_w * near_w / (far_w - near_w)};
}

}  // namespace

void scene_bounds(const Scene& scene, glm::vec3& centre, float& radius) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const Object& o : scene.objects) {
    if (o.type == ObjectType::sphere) {
      lo = glm::min(lo, o.center - glm::vec3(o.radius));
      hi = glm::max(hi, o.center + glm::vec3(o.radius));
    } else if (o.mesh) {
      glm::vec3 mlo, mhi;
      if (mesh_bounds(*o.mesh, mlo, mhi)) {
        lo = glm::min(lo, mlo);
        hi = glm::max(hi, mhi);
      }
    }
  }
  if (!(lo.x <= hi.x)) {
    centre = glm::vec3(0.0f);
    radius = 0.0f;
    return;
  }
  centre = 0.5f * (lo + hi);
  radius = 0.5f * glm::length(hi - lo);
}

RasterView camera_view(const Scene& scene, int width, int height) {
  const CameraFrame basis = make_camera_frame(scene.camera, width, height);
  RasterView v;
  v.origin = basis.eye;
  v.forward = basis.forward;
  v.right = basis.right;
  v.up = basis.up;
  v.scale = {basis.scale_x, basis.scale_y};
  glm::vec3 centre;
  float radius = 0.0f;
  scene_bounds(scene, centre, radius);
  // Along forward the scene lies within distance +- radius of its centre's; 1 % margins keep
  // the nearest and farthest surfaces off the planes. The near plane stays at least 1e-4 of the
  // far one: a 32-bit float depth buffer still orders surfaces 1e-6 of the range apart.
  const float mid = glm::dot(centre - v.origin, v.forward);
  const float far_w = std::max(1.01f * (mid + radius), 1e-3f);
  const float near_w = std::max(0.99f * (mid - radius), 1e-4f * far_w);
  v.depth = depth_mapping(near_w, far_w);
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
  const float near_w = std::max(1e-6f, 1e-6f * glm::length(light_position));
  v.depth = {1.0f, -2.0f * near_w};
  return v;
}

void set_view_uniforms(GLuint program, const RasterView& view) {
  set_uniform(program, "gloss_view_origin", &view.origin.x);
  set_uniform(program, "gloss_view_forward", &view.forward.x);
  set_uniform(program, "gloss_view_right", &view.right.x);
  set_uniform(program, "gloss_view_up", &view.up.x);
  set_uniform(program, "gloss_view_scale", view.scale.x, view.scale.y);
  set_uniform(program, "gloss_view_depth", view.depth.x, view.depth.y);
}

}  // namespace gloss

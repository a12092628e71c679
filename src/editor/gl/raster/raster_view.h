#pragma once
// The view a raster pass draws from, as shaders/raster_common.glsl's gloss_view_* uniforms: the
// document's camera for the shading passes, one face of a light's cube for the shadow pass. Also
// the boxes objects are drawn within, which decide the camera's depth range, what a view skips
// and when an impostor may drop its far faces.
#include <vector>

#include <glad/gl.h>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace gloss {

struct RasterView {
  glm::vec3 origin{0.0f}, forward{0.0f, 0.0f, -1.0f}, right{1.0f, 0.0f, 0.0f}, up{0.0f, 1.0f, 0.0f};
  glm::vec2 scale{1.0f};        // image-plane half extents at distance 1 along forward
  glm::vec2 depth{1.0f, 0.0f};  // (A, B): clip z = A w + B, w the distance along forward
  float near_w = 0.0f;          // w of the near plane: anything closer is clipped away
  // No perspective: x and y are distances across forward divided by scale, and w the distance
  // along it from the origin's plane (a directional light's shadow map).
  bool orthographic = false;
};

// The axis-aligned box one object's drawn geometry lies in: a sphere's impostor cube
// (raster_sphere.vert: centre +- 1.01 radius), a mesh's vertex bounds. empty: nothing to draw.
struct DrawnBox {
  glm::vec3 lo{0.0f}, hi{0.0f};
  bool empty = true;
};
std::vector<DrawnBox> drawn_boxes(const Scene& scene);

// The camera's view for a width x height image (scene/camera.h's basis in float, so the pixel
// centres are the ray tracer's). The far plane holds every drawn box; the near plane sits just
// before the nearest surface any pixel can see (a sphere's, or a mesh's box), but no nearer than
// 1e-6 of the far plane (when the eye is inside a box or on a surface). A 32-bit float depth
// buffer orders surfaces about 3e-8 w^2 / near apart at distance w: 3e-4 of the range at the
// far end when near is 1e-4 of it, 3e-2 at 1e-6 (an eye touching one surface of a scene that is
// large around it). Throws std::invalid_argument for a degenerate camera (as make_camera_basis).
RasterView camera_view(const Scene& scene, const std::vector<DrawnBox>& boxes, int width,
                       int height);

// Face k (0..5: +x, -x, +y, -y, +z, -z; raster_common.glsl's gloss_cube_face, same frames) of
// the cube around light_position: a 90 degree square view whose far plane is at infinity (the
// shadow pass keeps the nearest distance by blending, not by the depth test). Its frame is
// left-handed (cross(right, up) = forward), the camera's right-handed.
RasterView cube_face_view(const glm::vec3& light_position, int face);

// A spot's shadow view: a square frustum from the light along its unit direction whose
// half-angle across is the cutoff (cutoff <= 60 degrees; wider cones take the cube), far plane at
// infinity as the cube faces'.
RasterView spot_view(const glm::vec3& position, const glm::vec3& direction, float cutoff_degrees);

// A directional light's shadow view: orthographic along its unit direction, fitted to every
// drawn box (the scene as the light sees it), its origin on a plane just before the nearest
// corner and its far plane just past the farthest. Nothing drawn: a unit box at the origin.
RasterView directional_view(const glm::vec3& direction, const std::vector<DrawnBox>& boxes);

// Whether box can have a part inside view's frustum (a conservative test).
bool may_be_seen(const RasterView& view, const DrawnBox& box);

// Whether a sphere's impostor cube may be drawn with its near faces only: the eye is outside the
// cube and no part of it is in front of the near plane (where the near faces are clipped away,
// only the far faces cover the sphere).
bool near_faces_suffice(const RasterView& view, const DrawnBox& cube);

// Sets the gloss_view_* uniforms of program (in use).
void set_view_uniforms(GLuint program, const RasterView& view);

}  // namespace gloss

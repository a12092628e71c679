#pragma once
// The view a raster pass draws from, as shaders/raster_common.glsl's gloss_view_* uniforms: the
// document's camera for the shading passes, one face of a light's cube for the shadow pass.
#include <glad/gl.h>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace gloss {

struct RasterView {
  glm::vec3 origin{0.0f}, forward{0.0f, 0.0f, -1.0f}, right{1.0f, 0.0f, 0.0f}, up{0.0f, 1.0f, 0.0f};
  glm::vec2 scale{1.0f};        // image-plane half extents at distance 1 along forward
  glm::vec2 depth{1.0f, 0.0f};  // (A, B): clip z = A w + B, w the distance along forward
};

// The camera's view for a width x height image (scene/camera.h's basis in float, so the pixel
// centres are the ray tracer's), with near and far planes around the scene's bounds.
// Throws std::invalid_argument for a degenerate camera (as make_camera_basis).
RasterView camera_view(const Scene& scene, int width, int height);

// Face k (0..5: +x, -x, +y, -y, +z, -z; raster_common.glsl's gloss_cube_face, same frames) of the cube around
// light_position: a 90 degree square view whose far plane is at infinity (the shadow pass keeps
// the nearest distance by blending, not by the depth test).
RasterView cube_face_view(const glm::vec3& light_position, int face);

// Sets the gloss_view_* uniforms of program (in use).
void set_view_uniforms(GLuint program, const RasterView& view);

// Centre and radius of a sphere that holds every object of scene (radius 0 for none).
void scene_bounds(const Scene& scene, glm::vec3& centre, float& radius);

}  // namespace gloss

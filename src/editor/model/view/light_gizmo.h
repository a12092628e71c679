#pragma once
// Where the viewport draws a light's handles and what dragging them does (GL-free). A point or
// spot light has its marker at its position; a spot light also its cone, ending in an aim handle
// on its axis; a directional light an arrow that ends at the camera's target and starts at its
// handle, so the arrow shows the way the light travels across the scene. Dragging an aim handle
// turns the light's direction towards (spot) or from (directional) the dragged point; a
// headlight's direction is kept in camera space (scene/light.h).
#include <glm/vec3.hpp>

#include "scene/camera.h"
#include "scene/light.h"

namespace gloss {

struct LightGizmo {
  bool positioned = true;  // a marker at position (point and spot lights)
  bool aimed = false;      // a direction with a handle (directional and spot lights)
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // world, unit: the way the light travels
  glm::vec3 handle{0.0f};    // spot: position + length direction; directional: target - length
                             // direction
  float length = 1.0f;       // world units from the apex (spot) or the target (directional)
  float cone_radius = 0.0f;  // spot: the cone's radius at the handle (cutoff, drawn to 80 deg)
};

LightGizmo light_gizmo(const Light& light, const Camera& camera);

// The light's `direction` field once its aim handle is dragged to world point p (its own
// frame: camera space for a headlight). Keeps the old direction when p gives none.
glm::vec3 direction_for_handle(const Light& light, const Camera& camera, const glm::vec3& p);

// One step of "orbit light": the light turned by degrees about the vertical axis through
// centre, counter-clockwise seen from above: a point light's position, a spot's position and
// direction, a directional light's direction (a headlight turns with the camera: unchanged).
Light orbited_light(const Light& light, const glm::vec3& centre, float degrees);

}  // namespace gloss

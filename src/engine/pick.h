#pragma once
// Ray queries the editor asks of a scene through its Embree twin: which object is under a point
// of the image (click to select), and which surface is straight below a point (setting a new
// object down). Hidden objects are not in the twin, so neither query meets them.
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace gloss {

// Object index hit by the primary ray through image position (px, py) in pixels of a
// width x height view of scene.camera (pixel centres at +0.5), or -1 for none.
int pick_object(const Scene& scene, int width, int height, float px, float py);

// The first surface met by a ray from a point straight down (-y): the object hit (-1 for none)
// and the height y of the hit.
struct SurfaceBelow {
  int object = -1;
  float y = 0.0f;
};
// One answer per point, from one Embree build of scene.
std::vector<SurfaceBelow> surfaces_below(const Scene& scene, const std::vector<glm::vec3>& points);

// Whether each point is seen from the camera's eye: no object between the eye and it (a hit
// closer than 0.999 of its distance hides it). One Embree build of scene.
std::vector<bool> seen_from_eye(const Scene& scene, const std::vector<glm::vec3>& points);

}  // namespace gloss

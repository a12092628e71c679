#pragma once
// The viewport's transform gizmo as maths, free of any window system (the drawing and the mouse
// are editor/ui/viewport/gizmo.cpp's). Three modes: move (drag along a world axis, in a plane of
// two of them, or in the plane facing the camera), rotate (about a world axis, through the
// gizmo's centre) and scale (along an object's own axis, or uniformly), each applied to the
// transforms of the selected objects (scene/object_transform.h). A drag is computed from its
// start every frame, never by accumulating steps, so it is exact and returns when the mouse does.
// Image positions are pixels of a width x height view, y down, as in camera_controller.h.
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/camera.h"
#include "scene/scene.h"

namespace gloss {

enum class GizmoMode { move, rotate, scale };
// x, y, z: an axis; xy, yz, zx: a plane (move); view: the centre disc (move in the plane facing
// the camera; scale uniformly). Rotation rings are x, y, z.
enum class GizmoHandle { none, x, y, z, xy, yz, zx, view };

constexpr float kGizmoPixels = 90.0f;         // an axis's length on screen
constexpr float kGizmoRotateSnapDeg = 15.0f;  // rotation steps with snapping
constexpr float kGizmoScaleSnap = 0.1f;       // scale factor steps with snapping

// Where the gizmo is and how it looks from the camera.
struct GizmoFrame {
  glm::vec3 centre{0.0f};
  glm::vec3 axes[3];       // world x, y, z; in scale mode the primary object's own axes
  float world_length = 1;  // kGizmoPixels in world units at the centre's depth
  bool visible = false;    // the centre is in front of the eye
};

// The gizmo for the selected objects (indices into scene.objects) seen through camera (the
// scene's, or a pane's wider one): its centre is the mean of their placed pivots (pivot +
// translate).
GizmoFrame gizmo_frame(const Scene& scene, const Camera& camera, const std::vector<int>& objects,
                       GizmoMode mode, int width, int height);
// Seen through the scene's camera.
inline GizmoFrame gizmo_frame(const Scene& scene, const std::vector<int>& objects, GizmoMode mode,
                              int width, int height) {
  return gizmo_frame(scene, scene.camera, objects, mode, width, height);
}

// The handle under image position px, or none; tolerance in pixels.
GizmoHandle gizmo_hit(const Camera& camera, int width, int height, const GizmoFrame& frame,
                      GizmoMode mode, const glm::vec2& px, float tolerance = 7.0f);

// The points of a rotation ring (a circle of radius world_length about axis), for drawing and
// hit tests; n points, the last joining the first.
std::vector<glm::vec3> gizmo_ring(const GizmoFrame& frame, int axis, int n = 48);

// The grid a move snaps to: a power of ten near a quarter of the gizmo's world length.
float gizmo_move_snap(const GizmoFrame& frame);

// A drag in progress: the objects and their transforms at the press, where it started.
struct GizmoDrag {
  GizmoMode mode = GizmoMode::move;
  GizmoHandle handle = GizmoHandle::none;
  GizmoFrame frame;  // at the press
  std::vector<int> objects;
  std::vector<ObjectTransform> starts;  // parallel to objects
  std::vector<bool> spheres;            // parallel: a sphere scales uniformly only
  glm::vec2 press{0.0f};                // image position of the press
};

// The transforms of drag.objects with the mouse at px (snap: steps of gizmo_move_snap,
// kGizmoRotateSnapDeg or kGizmoScaleSnap). The amount is also returned (a move's world vector,
// a rotation's degrees in x, a scale's factor in x) for the viewport's readout.
std::vector<ObjectTransform> gizmo_transforms(const Camera& camera, int width, int height,
                                              const GizmoDrag& drag, const glm::vec2& px, bool snap,
                                              glm::vec3* amount = nullptr);

// The rotation by degrees about the unit axis (right-handed).
glm::dmat3 axis_rotation(const glm::dvec3& axis, double degrees);

}  // namespace gloss

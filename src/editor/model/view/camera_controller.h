#pragma once
// The viewport's mouse gestures as camera maths, free of any window system: orbit (camera.h's
// orbit_camera), pan, zoom, and the projections used to draw and drag the light marker. Image
// positions are pixels of a width x height view, y down, (x + 0.5, y + 0.5) = pixel (x, y).
#include <glm/vec2.hpp>

#include "scene/camera.h"
#include "scene/scene.h"

namespace gloss {

constexpr float kOrbitDegreesPerPixel = 0.3f;  // a 300-pixel drag turns 90 degrees
constexpr float kZoomPerStep = 0.85f;          // eye-target distance factor per wheel step
constexpr float kMinViewDistance = 1e-3f;      // world units

// Moves eye and target together in the view plane so the point at the target's depth follows
// the cursor: dx, dy in pixels (y down) of a view view_height pixels tall.
Camera pan_camera(const Camera& camera, float dx_px, float dy_px, int view_height);

// Moves the eye toward the target (steps > 0) or away: distance * kZoomPerStep^steps.
Camera zoom_camera(const Camera& camera, float steps);

// Image position of world point p; false when p is not in front of the eye.
bool project_point(const Camera& camera, int width, int height, const glm::vec3& p,
                   glm::vec2& image_position);

// The world point under image position px that has the same depth along the view axis as
// anchor: dragging a light keeps it in the plane facing the camera.
glm::vec3 point_at_depth(const Camera& camera, int width, int height, const glm::vec2& px,
                         const glm::vec3& anchor);

// The camera of a pane whose aspect (width / height) differs from the document's: it sees
// everything the document's camera sees, centred, and more of the scene on the two sides the
// pane has room on (a taller pane: a wider vertical field of view; a wider pane: the same one).
// The document's frame is then the centred rectangle of its aspect in the pane (pane_layout.h).
Camera overscan_camera(const Camera& camera, float document_aspect, float pane_aspect);

// Where "Add light" puts a new light: in view, upper right of the image (70% across, 25% down)
// at half the target's depth, so its marker is on screen and it lights the front of the scene.
glm::vec3 new_light_position(const Camera& camera, int width, int height);

// A marker for world point p in a width x height image: on screen, its projection; off screen
// (outside the image or behind the eye), the point of the rectangle inset by margin pixels
// (top_margin at the top, where a pane's label sits; < 0: margin) in the direction of p from the
// image centre, with on_screen false. direction: unit vector in image coordinates (y down) from
// the centre toward p. The viewport draws the marker and tests clicks at this one position.
struct EdgeMarker {
  glm::vec2 position{0.0f};
  glm::vec2 direction{0.0f, -1.0f};
  bool on_screen = false;
};
EdgeMarker edge_marker(const Camera& camera, int width, int height, const glm::vec3& p,
                       float margin, float top_margin = -1.0f);

// p moved by delta (pixels, y down) in the plane facing the camera, at the scale of p's depth
// (behind or beside the eye: of its distance): dragging an off-view light's arrow moves the
// light as the arrow moves, until it comes into view.
glm::vec3 move_in_view_plane(const Camera& camera, int width, int height, const glm::vec3& p,
                             const glm::vec2& delta);

// The image rectangle (lo, hi; y down) that holds the projection of object's axis-aligned
// bounds (a sphere's centre +- radius, a mesh's bounds): the viewport frames the selected object
// with it. False when any corner is behind the eye or the object has no extent.
bool screen_bounds(const Camera& camera, int width, int height, const Object& object, glm::vec2& lo,
                   glm::vec2& hi);

// The camera looking at the box lo..hi (world units) from the side it looks from now: the target
// at the box's centre, the eye back along the view direction until the box's bounding sphere
// fits the narrower of the two fields of view (aspect: width / height) with 10% to spare. The
// editor's "frame the selection" (key F).
Camera frame_camera(const Camera& camera, const glm::vec3& lo, const glm::vec3& hi, float aspect);

// p rotated by degrees about the vertical (+y) axis through centre, counter-clockwise seen from
// above.
glm::vec3 rotate_about_y(const glm::vec3& p, const glm::vec3& centre, float degrees);

}  // namespace gloss

// The viewport's camera maths, against values worked out by hand from the camera of
// docs/spec/shading.md.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "editor/model/view/camera_controller.h"
#include "editor/model/view/heat_map.h"

namespace gloss {
namespace {

Camera front_camera() {
  Camera c;
  c.eye = {0.0f, 0.0f, 5.0f};
  c.target = {0.0f, 0.0f, 0.0f};
  c.fov_y = 90.0f;  // tan(45 deg) = 1: the image spans y in [-d, d] at depth d
  return c;
}

TEST(CameraController, TheTargetProjectsToTheImageCentre) {
  glm::vec2 at;
  ASSERT_TRUE(project_point(front_camera(), 200, 100, glm::vec3(0.0f), at));
  EXPECT_NEAR(at.x, 100.0f, 1e-4f);
  EXPECT_NEAR(at.y, 50.0f, 1e-4f);
}

TEST(CameraController, ProjectionFollowsTheSpecsPixelMapping) {
  // At depth 5 with fov 90 the top edge is y = 5; a point at y = 2.5 sits a quarter of the way
  // down a 100-pixel image. Aspect 2: x spans [-10, 10], so x = 5 is at 3/4 of 200 pixels.
  glm::vec2 at;
  ASSERT_TRUE(project_point(front_camera(), 200, 100, glm::vec3(5.0f, 2.5f, 0.0f), at));
  EXPECT_NEAR(at.x, 150.0f, 1e-3f);
  EXPECT_NEAR(at.y, 25.0f, 1e-3f);
}

TEST(CameraController, ANewLightIsInViewUpperRightAtHalfTheTargetDepth) {
  const Camera c = front_camera();
  const glm::vec3 p = new_light_position(c, 200, 100);
  EXPECT_NEAR(p.z, 2.5f, 1e-4f);  // half way from the eye (z = 5) to the target (z = 0)
  glm::vec2 at;
  ASSERT_TRUE(project_point(c, 200, 100, p, at));
  EXPECT_NEAR(at.x, 140.0f, 1e-3f);  // 70% across
  EXPECT_NEAR(at.y, 25.0f, 1e-3f);   // 25% down
}

TEST(CameraController, EdgeMarkersClampOffScreenPointsToTheBorder) {
  const Camera c = front_camera();  // 200 x 100, margin 10: the inset border is x 10..190, y 10..90
  EdgeMarker m = edge_marker(c, 200, 100, glm::vec3(5.0f, 2.5f, 0.0f), 10.0f);
  EXPECT_TRUE(m.on_screen);
  EXPECT_NEAR(m.position.x, 150.0f, 1e-3f);
  // Straight above the top edge (y = 20 at depth 5 is 4 x the half height): top middle.
  m = edge_marker(c, 200, 100, glm::vec3(0.0f, 20.0f, 0.0f), 10.0f);
  EXPECT_FALSE(m.on_screen);
  EXPECT_NEAR(m.position.x, 100.0f, 1e-3f);
  EXPECT_NEAR(m.position.y, 10.0f, 1e-3f);
  EXPECT_NEAR(m.direction.y, -1.0f, 1e-5f);
  // Far right: right middle.
  m = edge_marker(c, 200, 100, glm::vec3(30.0f, 0.0f, 0.0f), 10.0f);
  EXPECT_NEAR(m.position.x, 190.0f, 1e-3f);
  EXPECT_NEAR(m.position.y, 50.0f, 1e-3f);
  // At depth 5, (x, y) = (10, 10) is x / (5 * aspect 2) = 1 half width (100 px) right and
  // y / 5 = 2 half heights (100 px) up: 45 degrees in pixels. The inset half sizes (90, 40) put
  // the top first, 40 px up, so 40 px right: x = 140.
  m = edge_marker(c, 200, 100, glm::vec3(10.0f, 10.0f, 0.0f), 10.0f);
  EXPECT_NEAR(m.position.x, 140.0f, 1e-3f);
  EXPECT_NEAR(m.position.y, 10.0f, 1e-3f);
  // Behind the eye and a little above: the side it is on, the top.
  m = edge_marker(c, 200, 100, glm::vec3(0.0f, 1.0f, 10.0f), 10.0f);
  EXPECT_FALSE(m.on_screen);
  EXPECT_NEAR(m.position.y, 10.0f, 1e-3f);
}

// The afternoon's bug: the arrow was drawn below the pane's label (y >= 30) but hit-tested at
// its unclamped edge position (y = margin), so a click on the drawn arrow missed it. The marker
// now carries the label's room itself, and the viewport draws and hit-tests that one position.
TEST(CameraController, AnOffViewArrowAtTheTopLeavesRoomForThePanesLabel) {
  const Camera c = front_camera();
  EdgeMarker m = edge_marker(c, 200, 100, glm::vec3(0.0f, 20.0f, 0.0f), 10.0f, 30.0f);
  EXPECT_FALSE(m.on_screen);
  EXPECT_NEAR(m.position.x, 100.0f, 1e-3f);
  EXPECT_NEAR(m.position.y, 30.0f, 1e-3f);
  // Up and right at 45 degrees in pixels: the top's inset half height is now 50 - 30 = 20, so
  // 20 px up and 20 px right.
  m = edge_marker(c, 200, 100, glm::vec3(10.0f, 10.0f, 0.0f), 10.0f, 30.0f);
  EXPECT_NEAR(m.position.x, 120.0f, 1e-3f);
  EXPECT_NEAR(m.position.y, 30.0f, 1e-3f);
  // Below, the plain margin.
  m = edge_marker(c, 200, 100, glm::vec3(0.0f, -20.0f, 0.0f), 10.0f, 30.0f);
  EXPECT_NEAR(m.position.y, 90.0f, 1e-3f);
}

// Dragging an off-view light's arrow brings the light under the cursor at the depth of the
// camera's target, wherever it was (beside the eye, where its own depth would barely move it).
TEST(CameraController, AnOffViewLightIsBroughtToTheTargetsDepth) {
  const Camera c = front_camera();            // 200 x 100, target at depth 5, fov 90
  const glm::vec3 beside(0.0f, 20.0f, 4.9f);  // depth 0.1, far above the view
  // The cursor a quarter of the way down: y = (1 - 2 x 25 / 100) x 5 = 2.5 at depth 5.
  const glm::vec3 moved = point_at_depth(c, 200, 100, {100.0f, 25.0f}, c.target);
  EXPECT_NEAR(moved.x, 0.0f, 1e-4f);
  EXPECT_NEAR(moved.y, 2.5f, 1e-4f);
  EXPECT_NEAR(moved.z, 0.0f, 1e-4f);
  EXPECT_FALSE(edge_marker(c, 200, 100, beside, 10.0f).on_screen);
  EXPECT_TRUE(edge_marker(c, 200, 100, moved, 10.0f).on_screen);
}

// A pane taller than the document sees the document's view and more above and below it.
TEST(CameraController, AnOverscanCameraKeepsTheDocumentsFrameInside) {
  const Camera c = front_camera();  // fov 90, document 200 x 100 (aspect 2)
  // A 100 x 100 pane (aspect 1): tan(fov'/2) = 1 x 2 / 1 = 2, fov' = 2 atan 2 = 126.87 degrees.
  const Camera tall = overscan_camera(c, 2.0f, 1.0f);
  EXPECT_NEAR(tall.fov_y, 126.8699f, 1e-3f);
  // The document's corner (x, y) = (10, 5) at depth 5 lands on the pane's frame: its half width
  // (50 px) to the right, a quarter of the pane (25 px) up from the centre: (100, 25).
  glm::vec2 at;
  ASSERT_TRUE(project_point(tall, 100, 100, glm::vec3(10.0f, 5.0f, 0.0f), at));
  EXPECT_NEAR(at.x, 100.0f, 1e-3f);
  EXPECT_NEAR(at.y, 25.0f, 1e-3f);
  // A wider pane keeps the camera: the frame's height is the pane's.
  EXPECT_EQ(overscan_camera(c, 2.0f, 3.0f).fov_y, 90.0f);
}

TEST(CameraController, ScreenBoundsFrameASphereByItsNearestCorners) {
  // Unit sphere at the origin, eye at z = 5: the nearest bound corners are at depth 4, where a
  // unit is 1/4 of the half height (50 px) and 1/(4 x 2) of the half width (100 px): 12.5 px.
  Object sphere;
  sphere.radius = 1.0f;
  glm::vec2 lo, hi;
  ASSERT_TRUE(screen_bounds(front_camera(), 200, 100, sphere, lo, hi));
  EXPECT_NEAR(lo.x, 87.5f, 1e-3f);
  EXPECT_NEAR(hi.x, 112.5f, 1e-3f);
  EXPECT_NEAR(lo.y, 37.5f, 1e-3f);
  EXPECT_NEAR(hi.y, 62.5f, 1e-3f);
  sphere.center.z = 5.0f;  // around the eye: corners behind it
  EXPECT_FALSE(screen_bounds(front_camera(), 200, 100, sphere, lo, hi));
}

TEST(CameraController, PointsBehindTheEyeDoNotProject) {
  glm::vec2 at;
  EXPECT_FALSE(project_point(front_camera(), 200, 100, glm::vec3(0.0f, 0.0f, 6.0f), at));
}

TEST(CameraController, DraggingKeepsTheDepthAndFollowsTheCursor) {
  const Camera c = front_camera();
  const glm::vec3 anchor(1.0f, 1.0f, -1.0f);  // depth 6 along the view axis
  const glm::vec3 moved = point_at_depth(c, 200, 100, glm::vec2(150.0f, 25.0f), anchor);
  EXPECT_NEAR(moved.z, -1.0f, 1e-4f);
  glm::vec2 at;
  ASSERT_TRUE(project_point(c, 200, 100, moved, at));
  EXPECT_NEAR(at.x, 150.0f, 1e-3f);
  EXPECT_NEAR(at.y, 25.0f, 1e-3f);
}

TEST(CameraController, ZoomScalesTheDistance) {
  const Camera c = front_camera();
  EXPECT_NEAR(zoom_camera(c, 1.0f).eye.z, 5.0f * kZoomPerStep, 1e-5f);
  EXPECT_NEAR(zoom_camera(c, -2.0f).eye.z, 5.0f / (kZoomPerStep * kZoomPerStep), 1e-4f);
  EXPECT_GE(zoom_camera(c, 1000.0f).eye.z, kMinViewDistance * 0.999f);
}

TEST(CameraController, PanMovesEyeAndTargetTogether) {
  // A 50-pixel drag to the right in a 100-pixel-tall view at distance 5 with fov 90: the view
  // is 10 units tall, so the scene follows the cursor by 5 units and the camera moves -5 in x.
  const Camera moved = pan_camera(front_camera(), 50.0f, 0.0f, 100);
  EXPECT_NEAR(moved.eye.x, -5.0f, 1e-4f);
  EXPECT_NEAR(moved.target.x, -5.0f, 1e-4f);
  EXPECT_NEAR(moved.eye.z, 5.0f, 1e-5f);
}

TEST(CameraController, RotateAboutYIsCounterClockwiseFromAbove) {
  const glm::vec3 p =
      rotate_about_y(glm::vec3(2.0f, 1.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f), 90.0f);
  EXPECT_NEAR(p.x, 1.0f, 1e-5f);
  EXPECT_NEAR(p.y, 1.0f, 1e-6f);
  EXPECT_NEAR(p.z, -1.0f, 1e-5f);
}

TEST(HeatMap, RampEndsAndMidpoints) {
  EXPECT_EQ(heat_colour(-1.0f), kHeatRamp[0]);
  EXPECT_EQ(heat_colour(2.0f), kHeatRamp[kHeatRampSize - 1]);
  const glm::vec3 mid = heat_colour(0.125f);  // halfway between the first two stops
  EXPECT_NEAR(mid.x, 0.5f * (kHeatRamp[0].x + kHeatRamp[1].x), 1e-6f);
}

TEST(HeatMap, LargestDifferenceIsPerChannel) {
  Image a(2, 1), b(2, 1);
  a.at(1, 0) = {0.5f, 0.2f, 0.1f};
  b.at(1, 0) = {0.4f, 0.5f, 0.1f};
  EXPECT_NEAR(max_difference(a, b), 0.3f, 1e-6f);
  EXPECT_EQ(max_difference(a, Image(3, 1)), 0.0f);
}

TEST(CameraController, FramingPutsTheBoxInTheMiddleAndFillsTheView) {
  Camera camera;
  camera.eye = {0, 0, 20};
  camera.target = {0, 0, 0};
  camera.fov_y = 60;
  // A box of half-diagonal sqrt(3) at (5, 0, 0), seen at aspect 2: the vertical field is the
  // narrower, half 30 degrees; distance 1.1 sqrt(3) / sin(30) = 2.2 sqrt(3) along +z.
  const Camera framed = frame_camera(camera, {4, -1, -1}, {6, 1, 1}, 2.0f);
  EXPECT_EQ(framed.target, glm::vec3(5, 0, 0));
  EXPECT_NEAR(framed.eye.x, 5.0f, 1e-6f);
  EXPECT_NEAR(framed.eye.z, 2.2f * std::sqrt(3.0f), 1e-5f);
  // Tall and narrow (aspect 0.5): the horizontal half-angle, atan(tan 30 x 0.5), is narrower.
  const float half = std::atan(std::tan(3.14159265f / 6.0f) * 0.5f);
  EXPECT_NEAR(frame_camera(camera, {4, -1, -1}, {6, 1, 1}, 0.5f).eye.z,
              1.1f * std::sqrt(3.0f) / std::sin(half), 1e-4f);
}

}  // namespace
}  // namespace gloss

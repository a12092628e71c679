// The transform gizmo's maths (editor/model/view/gizmo.h). The camera looks down -z from
// (0, 0, 10) with a 90-degree field of view on a 201 x 201 view, so at depth 10 one pixel is
// 2 x 10 / 201 world units and pixel (100.5, 100.5) looks at the origin: every expected value is
// that figure times a number of pixels.
#include "editor/model/view/gizmo.h"

#include <gtest/gtest.h>

#include "scene/geometry/placement.h"

namespace gloss {
namespace {

constexpr int kSize = 201;
constexpr float kPerPixel = 20.0f / 201.0f;  // world units per pixel at depth 10

Scene scene_with_spheres(std::initializer_list<glm::vec3> centres) {
  Scene scene;
  scene.camera.eye = {0, 0, 10};
  scene.camera.target = {0, 0, 0};
  scene.camera.fov_y = 90;
  scene.materials.push_back(Material{});
  scene.material_names.push_back("m");
  for (const glm::vec3& c : centres) scene.objects.push_back(sphere_object("s", c, 1.0f, 0));
  return scene;
}

GizmoDrag start(const Scene& scene, std::vector<int> objects, GizmoMode mode, GizmoHandle handle,
                glm::vec2 press) {
  GizmoDrag d;
  d.mode = mode;
  d.handle = handle;
  d.frame = gizmo_frame(scene, objects, mode, kSize, kSize);
  d.objects = objects;
  for (int i : objects) {
    d.starts.push_back(scene.objects[static_cast<std::size_t>(i)].transform);
    d.spheres.push_back(scene.objects[static_cast<std::size_t>(i)].type == ObjectType::sphere);
  }
  d.press = press;
  return d;
}

TEST(Gizmo, TheFrameSitsOnThePlacedPivotsAndKeepsItsScreenSize) {
  Scene scene = scene_with_spheres({{2, 0, 0}, {-2, 0, 0}});
  scene.objects[0].transform.translate = {0, 1, 0};
  const GizmoFrame f = gizmo_frame(scene, {0, 1}, GizmoMode::move, kSize, kSize);
  EXPECT_EQ(f.centre, glm::vec3(0, 0.5f, 0));  // the mean of (2, 1, 0) and (-2, 0, 0)
  EXPECT_TRUE(f.visible);
  EXPECT_NEAR(f.world_length, kGizmoPixels * kPerPixel, 1e-5f);
  EXPECT_EQ(gizmo_move_snap(f), 1.0f);  // 0.25 x 8.96 = 2.2: the power of ten below is 1
}

TEST(Gizmo, HandlesAreWhereTheyAreDrawn) {
  const Scene scene = scene_with_spheres({{0, 0, 0}});
  const GizmoFrame f = gizmo_frame(scene, {0}, GizmoMode::move, kSize, kSize);
  const Camera& cam = scene.camera;
  EXPECT_EQ(gizmo_hit(cam, kSize, kSize, f, GizmoMode::move, {100.5f, 100.5f}), GizmoHandle::view);
  EXPECT_EQ(gizmo_hit(cam, kSize, kSize, f, GizmoMode::move, {160.5f, 102.0f}), GizmoHandle::x);
  EXPECT_EQ(gizmo_hit(cam, kSize, kSize, f, GizmoMode::move, {100.5f, 40.5f}), GizmoHandle::y);
  // The xy square spans 0.25..0.45 of 90 pixels along +x and +y (up the screen).
  EXPECT_EQ(gizmo_hit(cam, kSize, kSize, f, GizmoMode::move, {132.5f, 68.5f}), GizmoHandle::xy);
  EXPECT_EQ(gizmo_hit(cam, kSize, kSize, f, GizmoMode::move, {30.5f, 170.5f}), GizmoHandle::none);
  // Rotation: the z ring is a circle of 90 pixels about the centre; x and y are seen edge-on.
  EXPECT_EQ(gizmo_hit(cam, kSize, kSize, f, GizmoMode::rotate, {100.5f - 63.6f, 100.5f - 63.6f}),
            GizmoHandle::z);
}

TEST(Gizmo, AMoveAlongAnAxisFollowsTheCursorAndSnaps) {
  const Scene scene = scene_with_spheres({{0, 0, 0}});
  const GizmoDrag d = start(scene, {0}, GizmoMode::move, GizmoHandle::x, {120.5f, 100.5f});
  glm::vec3 amount;
  // 20 pixels right along the axis.
  std::vector<ObjectTransform> t =
      gizmo_transforms(scene.camera, kSize, kSize, d, {140.5f, 100.5f}, false, &amount);
  EXPECT_NEAR(t[0].translate.x, 20 * kPerPixel, 1e-5f);
  EXPECT_EQ(amount.x, t[0].translate.x);
  // 7 pixels off the axis the move stays on it, at the axis point nearest the cursor's ray.
  t = gizmo_transforms(scene.camera, kSize, kSize, d, {140.5f, 107.5f}, false);
  EXPECT_NEAR(t[0].translate.x, 20 * kPerPixel, 0.05f);
  EXPECT_EQ(t[0].translate.y, 0.0f);
  EXPECT_EQ(t[0].translate.z, 0.0f);
  t = gizmo_transforms(scene.camera, kSize, kSize, d, {140.5f, 100.5f}, true);
  EXPECT_EQ(t[0].translate.x, 2.0f);  // 1.99 to the grid of 1
  // Back where it started, exactly where it was (computed from the press, not accumulated).
  t = gizmo_transforms(scene.camera, kSize, kSize, d, {120.5f, 100.5f}, false);
  EXPECT_EQ(t[0].translate, glm::vec3(0.0f));
}

TEST(Gizmo, AMoveInAPlaneFollowsTheCursorInBothAxes) {
  const Scene scene = scene_with_spheres({{0, 0, 0}});
  const GizmoDrag d = start(scene, {0}, GizmoMode::move, GizmoHandle::xy, {130.5f, 70.5f});
  const std::vector<ObjectTransform> t =
      gizmo_transforms(scene.camera, kSize, kSize, d, {150.5f, 60.5f}, false);
  EXPECT_NEAR(t[0].translate.x, 20 * kPerPixel, 1e-5f);
  EXPECT_NEAR(t[0].translate.y, 10 * kPerPixel, 1e-5f);  // up the screen is +y
  EXPECT_NEAR(t[0].translate.z, 0.0f, 1e-6f);
}

TEST(Gizmo, ARotationTurnsASelectionAboutItsCentre) {
  // Two spheres at x = +-2: the centre is the origin. A quarter turn of the cursor about it,
  // from +x to +y on screen, is +90 degrees about z (which points at the viewer).
  const Scene scene = scene_with_spheres({{2, 0, 0}, {-2, 0, 0}});
  const GizmoDrag d = start(scene, {0, 1}, GizmoMode::rotate, GizmoHandle::z, {160.5f, 100.5f});
  const std::vector<ObjectTransform> t =
      gizmo_transforms(scene.camera, kSize, kSize, d, {100.5f, 40.5f}, false);
  EXPECT_NEAR(t[0].rotate.z, 90.0f, 1e-3f);
  // (2, 0, 0) about the origin by 90 degrees: (0, 2, 0); its pivot stays, so translate = (-2, 2).
  EXPECT_NEAR(t[0].translate.x, -2.0f, 1e-5f);
  EXPECT_NEAR(t[0].translate.y, 2.0f, 1e-5f);
  EXPECT_NEAR(t[1].translate.x, 2.0f, 1e-5f);
  EXPECT_NEAR(t[1].translate.y, -2.0f, 1e-5f);
  // 37 degrees with snapping is 30 (steps of 15).
  const float a = 37.0f * 3.14159265f / 180.0f;
  const std::vector<ObjectTransform> snapped = gizmo_transforms(
      scene.camera, kSize, kSize, d, {100.5f + 60 * std::cos(a), 100.5f - 60 * std::sin(a)}, true);
  EXPECT_NEAR(snapped[0].rotate.z, 30.0f, 1e-3f);
}

TEST(Gizmo, ScalingUniformlyAndAlongAnOwnAxis) {
  Scene scene = scene_with_spheres({{0, 0, 0}});
  GizmoDrag d = start(scene, {0}, GizmoMode::scale, GizmoHandle::view, {120.5f, 100.5f});
  // 20 pixels farther from the centre, of half the gizmo's 90: 1 + 20 / 45.
  std::vector<ObjectTransform> t =
      gizmo_transforms(scene.camera, kSize, kSize, d, {140.5f, 100.5f}, false);
  EXPECT_NEAR(t[0].scale.x, 1.0f + 20.0f / 45.0f, 1e-5f);
  EXPECT_EQ(t[0].translate, glm::vec3(0.0f));
  // From a press on the centre itself: 45 pixels out doubles it.
  d = start(scene, {0}, GizmoMode::scale, GizmoHandle::view, {100.5f, 100.5f});
  t = gizmo_transforms(scene.camera, kSize, kSize, d, {100.5f, 55.5f}, false);
  EXPECT_NEAR(t[0].scale.z, 2.0f, 1e-5f);
  // A sphere scales uniformly even from an axis handle.
  d = start(scene, {0}, GizmoMode::scale, GizmoHandle::x, {120.5f, 100.5f});
  t = gizmo_transforms(scene.camera, kSize, kSize, d, {130.5f, 100.5f}, false);
  EXPECT_NEAR(t[0].scale.y, 1.5f, 1e-5f);
  // A non-sphere scales along its own x only.
  d.spheres[0] = false;
  t = gizmo_transforms(scene.camera, kSize, kSize, d, {130.5f, 100.5f}, false);
  EXPECT_NEAR(t[0].scale.x, 1.5f, 1e-5f);
  EXPECT_EQ(t[0].scale.y, 1.0f);
}

TEST(Gizmo, AxisRotationIsRightHanded) {
  const glm::dvec3 y = axis_rotation({0, 0, 1}, 90) * glm::dvec3(1, 0, 0);
  EXPECT_NEAR(y.x, 0.0, 1e-12);
  EXPECT_NEAR(y.y, 1.0, 1e-12);
  const glm::dmat3 a = axis_rotation({1, 0, 0}, 30), b = rotation_matrix({30, 0, 0});
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(a[c][r], b[c][r], 1e-12);
  }
}

}  // namespace
}  // namespace gloss

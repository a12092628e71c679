// The raster path's projections (editor/gl/raster/raster_view.h) against the camera formula and the
// cube-face rule of shaders/raster_common.glsl, on the CPU (no GL needed): the projection must
// put a point on the ray through pixel (x + 0.5, y + 0.5) at that pixel's centre, and the cube
// face chosen for a direction must be the face whose frustum holds it.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "editor/gl/raster/raster_view.h"
#include "scene/camera.h"

namespace gloss {
namespace {

// raster_common.glsl's gloss_project, then the viewport transform: window x, y (y from the
// image's top, as gloss_project negates it) and the NDC depth.
glm::vec3 window(const RasterView& v, const glm::vec3& p, int width, int height) {
  const glm::vec3 d = p - v.origin;
  const float w = glm::dot(d, v.forward);
  const float x = glm::dot(d, v.right) / v.scale.x / w;
  const float y = -glm::dot(d, v.up) / v.scale.y / w;
  const float z = (v.depth.x * w + v.depth.y) / w;
  return {(x * 0.5f + 0.5f) * width, (y * 0.5f + 0.5f) * height, z};
}

TEST(RasterView, PixelCentresAreTheCameraFormulas) {
  Scene scene;
  scene.camera.eye = {1.0f, 2.0f, 6.0f};
  scene.camera.target = {0.0f, 0.5f, 0.0f};
  scene.camera.fov_y = 35.0f;
  Object sphere;
  sphere.radius = 2.0f;
  scene.objects.push_back(sphere);
  const int w = 64, h = 48;
  const RasterView view = camera_view(scene, drawn_boxes(scene), w, h);
  const CameraFrame basis = make_camera_frame(scene.camera, w, h);
  for (int y : {0, 17, 47}) {
    for (int x : {0, 31, 63}) {
      const glm::vec3 d = primary_direction(basis, x + 0.5f, y + 0.5f, w, h);
      const glm::vec3 p = basis.eye + 6.0f * d;  // inside the scene's bounds
      const glm::vec3 at = window(view, p, w, h);
      EXPECT_NEAR(at.x, x + 0.5f, 1e-4f);
      EXPECT_NEAR(at.y, y + 0.5f, 1e-4f);
      EXPECT_GT(at.z, -1.0f);  // between the near and far planes
      EXPECT_LT(at.z, 1.0f);
    }
  }
}

TEST(RasterView, NearAndFarPlanesHoldTheScene) {
  Scene scene;
  scene.camera.eye = {0.0f, 0.0f, 10.0f};  // looking down -z at a unit sphere, fov 40
  Object sphere;
  sphere.radius = 1.0f;
  scene.objects.push_back(sphere);
  const RasterView view = camera_view(scene, drawn_boxes(scene), 10, 10);
  // Far: the impostor cube's farthest corner, w = 10 + 1.01, and 1 % beyond. Near: the sphere's
  // nearest point, w = 10 - 1 (larger than its distance 9 times the widest cosine), 1 % before.
  const auto ndc_z = [&](float w) { return (view.depth.x * w + view.depth.y) / w; };
  EXPECT_NEAR(view.near_w, 0.99f * 9.0f, 1e-5f);
  EXPECT_NEAR(ndc_z(0.99f * 9.0f), -1.0f, 1e-5f);
  EXPECT_NEAR(ndc_z(1.01f * 11.01f), 1.0f, 1e-5f);
}

TEST(RasterView, NearPlaneFollowsTheNearestSurfaceNotTheScenesSize) {
  // A ground sphere of radius 1e4 below the eye, its top 1.6 units under it: a near plane at a
  // fixed share of the far one (about 2e4 away) would cut the ground in front of the eye.
  Scene scene;
  scene.camera.eye = {0.0f, 1.6f, 3.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  Object ground;
  ground.center = {0.0f, -1e4f, 0.0f};
  ground.radius = 1e4f;
  scene.objects.push_back(ground);
  const RasterView view = camera_view(scene, drawn_boxes(scene), 64, 48);
  EXPECT_GT(view.near_w, 0.0f);
  EXPECT_LT(view.near_w, 1.6f);  // below the ground's nearest point's distance
}

TEST(RasterView, ImpostorsKeepTheirFarFacesWhenTheNearOnesMayBeClipped) {
  Scene scene;
  Object sphere;
  scene.objects.push_back(sphere);  // unit sphere at the origin; cube +-1.01
  scene.camera.fov_y = 60.0f;
  scene.camera.eye = {0.0f, 0.0f, 5.0f};  // cube's nearest w 3.99, near plane 0.99 x 4
  RasterView view = camera_view(scene, drawn_boxes(scene), 32, 32);
  EXPECT_TRUE(near_faces_suffice(view, drawn_boxes(scene)[0]));
  // Along a diagonal the cube's corner (w = 0.49 sqrt 3 = 0.85) is nearer than the sphere's
  // point (w = 1.5 sqrt 3 - 1 = 1.60) that sets the near plane: the near faces are cut.
  scene.camera.eye = {1.5f, 1.5f, 1.5f};
  view = camera_view(scene, drawn_boxes(scene), 32, 32);
  EXPECT_FALSE(near_faces_suffice(view, drawn_boxes(scene)[0]));
  scene.camera.eye = {0.9f, 0.7f, 0.9f};  // inside the cube
  view = camera_view(scene, drawn_boxes(scene), 32, 32);
  EXPECT_FALSE(near_faces_suffice(view, drawn_boxes(scene)[0]));
}

// raster_common.glsl's gloss_cube_face: the major axis, +x, -x, +y, -y, +z, -z.
int cube_face(const glm::vec3& d) {
  const glm::vec3 a = glm::abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0f ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0f ? 2 : 3;
  return d.z >= 0.0f ? 4 : 5;
}

TEST(RasterView, EachCubeFaceSeesTheDirectionsItsLookupPicks) {
  const glm::vec3 light(1.0f, -2.0f, 3.0f);
  for (int face = 0; face < 6; ++face) {
    const RasterView v = cube_face_view(light, face);
    // Orthonormal, every face with the same handedness.
    EXPECT_NEAR(glm::length(glm::cross(v.right, v.up) - v.forward), 0.0f, 1e-6f);
    // Directions across the face (NDC -0.9..0.9) are picked for this face.
    for (float s : {-0.9f, 0.0f, 0.9f}) {
      for (float t : {-0.9f, 0.3f, 0.9f}) {
        const glm::vec3 d = v.forward + s * v.right + t * v.up;
        EXPECT_EQ(cube_face(d), face) << "face " << face << " at " << s << ", " << t;
      }
    }
    // Far plane at infinity: inside the clip volume (z <= w) however far, up to the largest
    // coordinate a scene may have (scene/limits.h).
    for (float w : {1.0f, 1e3f, 1e15f}) EXPECT_LE(v.depth.x * w + v.depth.y, w);
    EXPECT_GT(v.depth.x * 1e-5f + v.depth.y, -1e-5f);  // and 1e-5 from the light is not clipped
  }
}

}  // namespace
}  // namespace gloss

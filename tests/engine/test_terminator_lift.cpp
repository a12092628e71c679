// The shadow terminator's lift (shading/surface.h): how far the smooth surface of a triangle's
// vertex normals lies above the triangle, and how much of it a shadow ray takes. Values worked
// out by hand on one triangle: P0 = (0, 0, 0), P1 = (1, 0, 0), P2 = (0, 1, 0), face normal +z,
// n0 = n2 = +z and n1 tilted 60 degrees towards +x: (sqrt(3)/2, 0, 1/2).
#include <cmath>
#include <memory>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/trace/surface_table.h"
#include "shading/surface.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

const float kS3 = std::sqrt(3.0f);
const glm::vec3 kUp(0, 0, 1), kTilted(kS3 / 2, 0, 0.5f);
// dot(P_k, n_k): only P1 = (1, 0, 0) against n1 is not 0.
const glm::vec3 kPlanes(0.0f, kS3 / 2, 0.0f);

TEST(TerminatorLift, TheCentroidOfATriangleWithOneTiltedCorner) {
  // At the centroid (1/3, 1/3, 0): corners 0 and 2 have their planes through p (0). Corner 1:
  // dot(p - P1, n1) = -2/3 sqrt(3)/2 = -1/sqrt(3), below its plane; its share is
  // b1 * (1/sqrt(3)) * dot(n1, ng) = 1/3 * 1/sqrt(3) * 1/2 = sqrt(3)/18.
  const float b[3] = {1.0f / 3, 1.0f / 3, 1.0f / 3};
  const glm::vec3 p(1.0f / 3, 1.0f / 3, 0.0f);
  EXPECT_NEAR(terminator_lift(p, kUp, b, kUp, kTilted, kUp, kPlanes, 1.0f), kS3 / 18, 1e-6);
  // Seen from below (the two-sided rule turned the normals): that side is concave, no lift.
  EXPECT_EQ(terminator_lift(p, -kUp, b, kUp, kTilted, kUp, kPlanes, -1.0f), 0.0f);
}

TEST(TerminatorLift, NothingAtTheCornersAndOnAFlatTriangle) {
  const float at_p1[3] = {0, 1, 0};  // on corner 1's own plane
  EXPECT_EQ(terminator_lift(glm::vec3(1, 0, 0), kUp, at_p1, kUp, kTilted, kUp, kPlanes, 1.0f),
            0.0f);
  const float at_p0[3] = {1, 0, 0};  // weight 0 for corner 1
  EXPECT_EQ(terminator_lift(glm::vec3(0, 0, 0), kUp, at_p0, kUp, kTilted, kUp, kPlanes, 1.0f),
            0.0f);
  const float b[3] = {0.2f, 0.3f, 0.5f};
  const glm::vec3 flat(0.0f);
  EXPECT_EQ(terminator_lift(glm::vec3(0.3f, 0.5f, 0), kUp, b, kUp, kUp, kUp, flat, 1.0f), 0.0f);
}

TEST(TerminatorLift, TheSurfaceTableKeepsTheCornersPlanesAndSurfaceFromTheLift) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.normals = {kUp, kTilted, kUp};
  mesh.triangles = {{0, 1, 2}};
  Scene scene;
  Object o;
  o.type = ObjectType::mesh;
  o.shape = o.mesh = std::make_shared<const Mesh>(mesh);
  scene.objects.push_back(o);
  const SurfaceTable t = make_surface_table(scene);
  const std::uint32_t r = t.record(0, 0);
  EXPECT_EQ(t.kind[0], kSmoothTriangle);
  EXPECT_EQ(t.planes[0][r], 0.0f);
  EXPECT_NEAR(t.planes[1][r], kS3 / 2, 1e-7);
  EXPECT_EQ(t.planes[2][r], 0.0f);

  // The centroid hit from above (eye at z = 2) and from below.
  HitGeometry g;
  g.a = kUp;
  g.n0 = kUp;
  g.n1 = kTilted;
  g.n2 = kUp;
  g.planes = {t.planes[0][r], t.planes[1][r], t.planes[2][r]};
  g.u = g.v = 1.0f / 3;
  g.sphere = 0;
  g.smooth = 1;
  const glm::vec3 eye(1.0f / 3, 1.0f / 3, 2.0f);
  const Surface above = surface_from(g, eye, glm::dvec3(0, 0, -1), 2.0f);
  EXPECT_NEAR(above.lift, kS3 / 18, 1e-6);
  const Surface below =
      surface_from(g, glm::vec3(1.0f / 3, 1.0f / 3, -2.0f), glm::dvec3(0, 0, 1), 2.0f);
  EXPECT_EQ(below.lift, 0.0f);
  g.smooth = 0;  // a flat triangle shades and shadows from its face
  EXPECT_EQ(surface_from(g, eye, glm::dvec3(0, 0, -1), 2.0f).lift, 0.0f);
}

TEST(TerminatorLift, AShadowRayTakesAllOfItIntoTheTrianglesPlaneAndNoneAboveACosineOfATenth) {
  Surface s;
  s.p = glm::vec3(0.0f);
  s.ng = kUp;
  s.n = kUp;
  s.v = kUp;
  s.lift = 0.1f;
  // t = 1: the offset without the lift is 4e-6 * (0 + 1).
  const float eps = 4e-6f;
  EXPECT_NEAR(shadow_ray_origin(s, 1.0f, glm::vec3(1, 0, 0)).z, eps + 0.1f, 1e-7);   // along it
  EXPECT_NEAR(shadow_ray_origin(s, 1.0f, glm::vec3(3, 0, -1)).z, eps + 0.1f, 1e-7);  // into it
  // dot(ng, l) = 0.05 for a unit l: half of it. The length of `towards` does not matter.
  const glm::vec3 half(std::sqrt(1.0f - 0.05f * 0.05f), 0, 0.05f);
  EXPECT_NEAR(shadow_ray_origin(s, 1.0f, half).z, eps + 0.05f, 1e-6);
  EXPECT_NEAR(shadow_ray_origin(s, 1.0f, 7.0f * half).z, eps + 0.05f, 1e-6);
  EXPECT_NEAR(shadow_ray_origin(s, 1.0f, glm::vec3(0.9f, 0, 0.2f)).z, eps, 1e-9);  // above
  EXPECT_NEAR(shadow_ray_origin(s, 1.0f, kUp).z, eps, 1e-9);
  // Never only along ng's side: x and y stay p's.
  EXPECT_EQ(shadow_ray_origin(s, 1.0f, glm::vec3(1, 0, 0)).x, 0.0f);
}

}  // namespace
}  // namespace gloss

// An object's transform: p' = pivot + translate + Rz Ry Rx S (p - pivot), degrees, x first
// (docs/scene-format.md). Every expected point below is worked out by hand in the comment beside
// it.
#include "scene/geometry/placement.h"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "scene/geometry/shapes.h"

namespace gloss {
namespace {

void expect_near(const glm::dvec3& got, const glm::dvec3& want, double tolerance = 1e-12) {
  EXPECT_NEAR(got.x, want.x, tolerance) << "x";
  EXPECT_NEAR(got.y, want.y, tolerance) << "y";
  EXPECT_NEAR(got.z, want.z, tolerance) << "z";
}

TEST(Placement, RotationsAreRightHandedInDegrees) {
  // About x by 90: y goes to z. About y by 90: z goes to x. About z by 90: x goes to y.
  expect_near(rotation_matrix({90, 0, 0}) * glm::dvec3(0, 1, 0), {0, 0, 1});
  expect_near(rotation_matrix({0, 90, 0}) * glm::dvec3(0, 0, 1), {1, 0, 0});
  expect_near(rotation_matrix({0, 0, 90}) * glm::dvec3(1, 0, 0), {0, 1, 0});
}

TEST(Placement, RotatesAboutXFirstThenYThenZ) {
  // (0, 1, 0): x by 90 -> (0, 0, 1); then y by 90 -> (1, 0, 0); then z by 90 -> (0, 1, 0).
  // Y first would leave (0, 1, 0) alone and x would then take it to (0, 0, 1).
  expect_near(rotation_matrix({90, 90, 0}) * glm::dvec3(0, 1, 0), {1, 0, 0});
  expect_near(rotation_matrix({90, 90, 90}) * glm::dvec3(0, 1, 0), {0, 1, 0});
  // (1, 0, 0): x leaves it; y by 90 -> (0, 0, -1); z leaves that.
  expect_near(rotation_matrix({90, 90, 90}) * glm::dvec3(1, 0, 0), {0, 0, -1});
}

TEST(Placement, PlacesAPointAboutThePivot) {
  ObjectTransform t;
  t.pivot = {1, 0, 0};
  t.translate = {0, 2, 0};
  t.rotate = {0, 0, 90};
  t.scale = {2, 1, 1};
  // p - pivot = (1, 0, 0); S: (2, 0, 0); Rz 90: (0, 2, 0); + pivot + translate: (1, 4, 0).
  expect_near(place_point(t, {2, 0, 0}), {1, 4, 0});
  // The pivot itself only moves by the translate.
  expect_near(place_point(t, {1, 0, 0}), {1, 2, 0});
}

TEST(Placement, ASphereStaysAnalyticItsCentreMovedAndItsRadiusScaled) {
  Object o = sphere_object("ball", {1, 2, 3}, 0.5f, 0);
  o.transform.translate = {1, 0, 0};
  o.transform.rotate = {0, 90, 0};
  o.transform.scale = glm::vec3(-2.0f);
  place_object(o);
  // The pivot follows the centre, so rotation and scale leave the centre where it is.
  EXPECT_EQ(o.transform.pivot, glm::vec3(1, 2, 3));
  EXPECT_EQ(o.center, glm::vec3(2, 2, 3));
  EXPECT_EQ(o.radius, 1.0f);                       // |s| r
  EXPECT_EQ(o.params.center, glm::vec3(1, 2, 3));  // the file's fields keep their meaning
  EXPECT_EQ(o.params.radius, 0.5f);
  EXPECT_EQ(o.mesh, nullptr);
}

TEST(Placement, ASphereTurnsAboutAGivenPivot) {
  Object o = sphere_object("ball", {1, 0, 0}, 1.0f, 0);
  o.transform.pivot = {0, 0, 0};
  o.transform.pivot_set = true;
  o.transform.rotate = {0, 0, 90};
  place_object(o);
  // (1, 0, 0) about the origin by 90 about z: (0, 1, 0).
  EXPECT_NEAR(o.center.x, 0.0f, 1e-7f);
  EXPECT_EQ(o.center.y, 1.0f);
  EXPECT_EQ(o.transform.pivot, glm::vec3(0, 0, 0));
}

Object unit_quad() {
  Object o;
  o.type = ObjectType::quad;
  o.params.quad[0] = {0, 0, 0};
  o.params.quad[1] = {2, 0, 0};
  o.params.quad[2] = {2, 0, 2};
  o.params.quad[3] = {0, 0, 2};
  o.shape = std::make_shared<const Mesh>(
      make_quad(o.params.quad[0], o.params.quad[1], o.params.quad[2], o.params.quad[3]));
  return o;
}

TEST(Placement, TheIdentityKeepsTheMeshItself) {
  Object o = unit_quad();
  place_object(o);
  EXPECT_EQ(o.mesh, o.shape);  // not a copy: old scenes render bit for bit as before
  EXPECT_EQ(o.transform.pivot, glm::vec3(1, 0, 1));  // the quad's centroid
}

TEST(Placement, AMeshIsPlacedVertexByVertex) {
  Object o = unit_quad();
  o.transform.rotate = {90, 0, 0};
  o.transform.translate = {0, 0, -1};
  place_object(o);
  ASSERT_NE(o.mesh, o.shape);
  // Corner (2, 0, 2): minus the centroid (1, 0, 1) is (1, 0, 1); x by 90 takes (1, 0, 1) to
  // (1, -1, 0); plus the centroid and the translate: (2, -1, 0).
  const glm::vec3 p = o.mesh->positions[2];
  EXPECT_FLOAT_EQ(p.x, 2.0f);
  EXPECT_FLOAT_EQ(p.y, -1.0f);
  EXPECT_NEAR(p.z, 0.0f, 1e-7f);
  EXPECT_EQ(o.shape->positions[2], glm::vec3(2, 0, 2));  // the own triangles are untouched
}

TEST(Placement, NormalsFollowTheInverseTransposeAndMirrorsRewind) {
  Object o = unit_quad();
  Mesh smooth = *o.shape;
  const glm::vec3 n = glm::normalize(glm::vec3(1, 1, 0));
  smooth.normals.assign(smooth.positions.size(), n);
  o.shape = std::make_shared<const Mesh>(smooth);
  o.transform.scale = {2, 1, 1};
  place_object(o);
  // The inverse transpose of diag(2, 1, 1) is diag(1/2, 1, 1): (1, 1, 0)/sqrt2 -> (1/2, 1, 0),
  // normalised (1, 2, 0)/sqrt5.
  const glm::vec3 want = glm::normalize(glm::vec3(1, 2, 0));
  EXPECT_NEAR(o.mesh->normals[0].x, want.x, 1e-6f);
  EXPECT_NEAR(o.mesh->normals[0].y, want.y, 1e-6f);
  EXPECT_EQ(o.mesh->triangles[0], o.shape->triangles[0]);
  o.transform.scale = {-1, 1, 1};  // a mirror: triangles are wound the other way
  place_object(o);
  const glm::uvec3 a = o.shape->triangles[0], b = o.mesh->triangles[0];
  EXPECT_EQ(b, glm::uvec3(a.x, a.z, a.y));
}

TEST(Placement, TangentsTurnWithTheObjectAndMirrorsFlipTheirHandedness) {
  Object o = unit_quad();
  Mesh textured = *o.shape;
  textured.tangents.assign(textured.positions.size(), glm::vec4(1, 0, 0, 1));
  o.shape = std::make_shared<const Mesh>(textured);
  o.transform.rotate = {0, 90, 0};
  place_object(o);
  // y by 90 takes x to -z: the tangent (1, 0, 0) becomes (0, 0, -1), handedness kept.
  const glm::vec4 t = o.mesh->tangents[0];
  EXPECT_NEAR(t.x, 0.0f, 1e-7f);
  EXPECT_NEAR(t.z, -1.0f, 1e-7f);
  EXPECT_EQ(t.w, 1.0f);
  o.transform.rotate = {0, 0, 0};
  o.transform.scale = {-3, 1, 1};  // a mirror along x: (-3, 0, 0) normalised, handedness -1
  place_object(o);
  EXPECT_EQ(o.mesh->tangents[0], glm::vec4(-1, 0, 0, -1));
}

TEST(Placement, EulerAnglesComeBackFromTheirMatrix) {
  for (const glm::vec3 angles : {glm::vec3(10, 20, 30), glm::vec3(-170, 45, 100),
                                 glm::vec3(0, -80, 0), glm::vec3(33, 0, -150)}) {
    const glm::vec3 back = euler_degrees(rotation_matrix(angles), angles);
    EXPECT_NEAR(back.x, angles.x, 1e-4f);
    EXPECT_NEAR(back.y, angles.y, 1e-4f);
    EXPECT_NEAR(back.z, angles.z, 1e-4f);
  }
}

TEST(Placement, EulerAnglesStayNearTheOnesGiven) {
  // 350 degrees about z is -10; near 340 it reads 350, not -10.
  EXPECT_NEAR(euler_degrees(rotation_matrix({0, 0, 350}), {0, 0, 340}).z, 350.0f, 1e-4f);
  EXPECT_NEAR(euler_degrees(rotation_matrix({0, 0, 350})).z, -10.0f, 1e-4f);
  // (180, 180, 180) is the identity; near it the angles read (180, 180, 180), not zeros.
  const glm::vec3 half_turns = euler_degrees(rotation_matrix({0, 0, 0}), {180, 180, 180});
  EXPECT_NEAR(half_turns.x, 180.0f, 1e-4f);
  EXPECT_NEAR(half_turns.y, 180.0f, 1e-4f);
  EXPECT_NEAR(half_turns.z, 180.0f, 1e-4f);
}

TEST(Placement, EulerAnglesAtGimbalLockKeepX) {
  // y = 90: only x - z is defined; x stays at the 30 given, z follows (x - z = 30 - 50).
  const glm::dmat3 r = rotation_matrix({30, 90, 50});
  const glm::vec3 back = euler_degrees(r, {30, 90, 50});
  EXPECT_NEAR(back.x, 30.0f, 1e-4f);
  EXPECT_NEAR(back.y, 90.0f, 1e-4f);
  EXPECT_NEAR(back.z, 50.0f, 1e-3f);
  const glm::dmat3 again = rotation_matrix(back);
  for (int c = 0; c < 3; ++c) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(again[c][k], r[c][k], 1e-9);
  }
}

TEST(Placement, BoundsOfThePlacedObject) {
  Object o = sphere_object("ball", {0, 1, 0}, 1.0f, 0);
  o.transform.scale = glm::vec3(3.0f);
  place_object(o);
  glm::vec3 lo, hi;
  ASSERT_TRUE(object_bounds(o, lo, hi));
  EXPECT_EQ(lo, glm::vec3(-3, -2, -3));
  EXPECT_EQ(hi, glm::vec3(3, 4, 3));
}

}  // namespace
}  // namespace gloss

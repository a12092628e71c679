#include "scene/geometry/shapes.h"

#include <algorithm>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

namespace gloss {
namespace {

glm::vec3 face_cross(const Mesh& mesh, const glm::uvec3& t) {
  return glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                    mesh.positions[t.z] - mesh.positions[t.x]);
}

TEST(Shapes, QuadIsTwoFlatTrianglesWoundLikeItsCorners) {
  // Unit square in the z = 0 plane, counter-clockwise seen from +z.
  const Mesh quad = make_quad({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
  EXPECT_FALSE(quad.smooth());
  ASSERT_EQ(quad.triangles.size(), 2u);
  EXPECT_EQ(quad.triangles[0], glm::uvec3(0, 1, 2));
  EXPECT_EQ(quad.triangles[1], glm::uvec3(0, 2, 3));
  float area = 0.0f;
  for (const glm::uvec3& t : quad.triangles) {
    const glm::vec3 c = face_cross(quad, t);
    EXPECT_EQ(glm::normalize(c), glm::vec3(0, 0, 1));
    area += 0.5f * glm::length(c);
  }
  EXPECT_FLOAT_EQ(area, 1.0f);
}

// Box 1 x 2 x 3: 12 triangles on 24 vertices (four per face, for its texture coordinates),
// faces of area 2, 6, 3 (twice each, 22 in all),
// every face normal along an axis and pointing away from the centre.
void expect_outward_box(const Mesh& box) {
  EXPECT_FALSE(box.smooth());
  EXPECT_EQ(box.positions.size(), 24u);
  ASSERT_EQ(box.triangles.size(), 12u);
  const glm::vec3 centre(0.5f, 1.0f, 1.5f);
  float area = 0.0f, volume = 0.0f;
  for (const glm::uvec3& t : box.triangles) {
    const glm::vec3 c = face_cross(box, t);
    const glm::vec3 n = glm::normalize(c);
    const glm::vec3 a = glm::abs(n);
    EXPECT_FLOAT_EQ(std::max({a.x, a.y, a.z}), 1.0f);  // along an axis
    const glm::vec3 middle = (box.positions[t.x] + box.positions[t.y] + box.positions[t.z]) / 3.0f;
    EXPECT_GT(glm::dot(middle - centre, n), 0.0f);
    area += 0.5f * glm::length(c);
    // Divergence theorem: the signed volume is positive only for outward winding.
    volume += glm::dot(box.positions[t.x], c) / 6.0f;
  }
  EXPECT_FLOAT_EQ(area, 22.0f);
  EXPECT_NEAR(volume, 6.0f, 1e-5f);
}

TEST(Shapes, BoxHasTwelveOutwardTrianglesAndTheRightArea) {
  const Mesh box = make_box({0, 0, 0}, {1, 2, 3});
  expect_outward_box(box);
  glm::vec3 lo, hi;
  ASSERT_TRUE(mesh_bounds(box, lo, hi));
  EXPECT_EQ(lo, glm::vec3(0, 0, 0));
  EXPECT_EQ(hi, glm::vec3(1, 2, 3));
}

TEST(Shapes, BoxWithSwappedCornersStillWindsOutward) {
  expect_outward_box(make_box({1, 0, 3}, {0, 2, 0}));
}

}  // namespace
}  // namespace gloss

#include "scene/geometry/mesh.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace gloss {
namespace {

Mesh unit_right_triangle() {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}};
  return mesh;
}

TEST(Mesh, DropsZeroAreaAndNonFiniteTrianglesOnly) {
  Mesh mesh;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {1, 0, 0}, {nan, 0, 0}};
  mesh.triangles = {
      {0, 1, 2},  // right triangle, area 1/2: kept
      {0, 0, 1},  // repeated index
      {0, 1, 3},  // collinear on the x axis
      {1, 4, 2},  // distinct indices, same position (1, 0, 0)
      {0, 1, 5},  // NaN corner
      {2, 1, 0},  // the first triangle wound the other way: kept
  };
  EXPECT_EQ(drop_degenerate_triangles(mesh), 4u);
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.triangles[0], glm::uvec3(0, 1, 2));
  EXPECT_EQ(mesh.triangles[1], glm::uvec3(2, 1, 0));
  EXPECT_EQ(mesh.positions.size(), 6u);  // positions are left alone
}

TEST(Mesh, KeepsSmallButValidTriangles) {
  Mesh mesh = unit_right_triangle();
  for (glm::vec3& p : mesh.positions) p *= 1e-4f;  // area 5e-9
  EXPECT_EQ(drop_degenerate_triangles(mesh), 0u);
  EXPECT_EQ(mesh.triangles.size(), 1u);
}

TEST(Mesh, DropsTrianglesWithOutOfRangeIndices) {
  Mesh mesh = unit_right_triangle();
  mesh.triangles.push_back({0, 1, 3});
  EXPECT_EQ(drop_degenerate_triangles(mesh), 1u);
  EXPECT_EQ(mesh.triangles.size(), 1u);
}

TEST(Mesh, TransformMovesPositionsAndUsesInverseTransposeForNormals) {
  Mesh mesh = unit_right_triangle();
  const glm::vec3 n = glm::normalize(glm::vec3(1, 1, 0));
  mesh.normals = {n, n, n};
  // Scale x by 2, then translate by (1, 2, 3).
  const glm::mat4 m =
      glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)), glm::vec3(2, 1, 1));
  transform_mesh(mesh, m);
  EXPECT_EQ(mesh.positions[0], glm::vec3(1, 2, 3));
  EXPECT_EQ(mesh.positions[1], glm::vec3(3, 2, 3));
  EXPECT_EQ(mesh.positions[2], glm::vec3(1, 3, 3));
  // Inverse transpose diag(1/2, 1, 1) takes (1, 1, 0) to (1/2, 1, 0): unit (1, 2, 0) / sqrt(5).
  const float s5 = std::sqrt(5.0f);
  for (const glm::vec3& m_n : mesh.normals) {
    EXPECT_NEAR(m_n.x, 1.0f / s5, 1e-6f);
    EXPECT_NEAR(m_n.y, 2.0f / s5, 1e-6f);
    EXPECT_NEAR(m_n.z, 0.0f, 1e-6f);
  }
}

TEST(Mesh, MirrorTransformRewindsSoWindingFollowsNormals) {
  Mesh mesh = unit_right_triangle();
  mesh.normals.assign(3, glm::vec3(0, 0, 1));  // agrees with the winding: cross(x, y) = z
  transform_mesh(mesh, glm::scale(glm::mat4(1.0f), glm::vec3(-1, 1, 1)));
  const glm::uvec3 t = mesh.triangles[0];
  const glm::vec3 face = glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                                    mesh.positions[t.z] - mesh.positions[t.x]);
  EXPECT_EQ(mesh.normals[0], glm::vec3(0, 0, 1));  // a mirror in x leaves a z normal alone
  EXPECT_GT(glm::dot(face, mesh.normals[0]), 0.0f);
}

TEST(Mesh, SingularTransformDropsNormals) {
  Mesh mesh = unit_right_triangle();
  mesh.normals.assign(3, glm::vec3(0, 0, 1));
  transform_mesh(mesh, glm::scale(glm::mat4(1.0f), glm::vec3(1, 0, 1)));
  EXPECT_FALSE(mesh.smooth());
  EXPECT_EQ(mesh.positions[2], glm::vec3(0, 0, 0));
}

TEST(Mesh, BoundsCoverAllPositions) {
  Mesh mesh;
  glm::vec3 lo, hi;
  EXPECT_FALSE(mesh_bounds(mesh, lo, hi));
  mesh.positions = {{1, -2, 3}, {-4, 5, 0.5f}, {0, 0, 7}};
  ASSERT_TRUE(mesh_bounds(mesh, lo, hi));
  EXPECT_EQ(lo, glm::vec3(-4, -2, 0.5f));
  EXPECT_EQ(hi, glm::vec3(1, 5, 7));
}

}  // namespace
}  // namespace gloss

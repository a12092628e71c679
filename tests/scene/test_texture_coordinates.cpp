// Texture coordinates and tangents of the shapes (docs/scene-format.md, "Texture coordinates"),
// checked against the documented directions, and MikkTSpace's handedness on mirrored (u, v).
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/geometry/shapes.h"
#include "scene/geometry/tangent_space.h"
#include "scene/geometry/teapot.h"
#include "shading/texturing.h"

namespace gloss {
namespace {

// dP/du and dP/dv of triangle k.
void derivatives(const Mesh& m, std::size_t k, glm::vec3& dpdu, glm::vec3& dpdv) {
  const glm::uvec3 t = m.triangles[k];
  triangle_uv_derivatives(m.positions[t.x], m.positions[t.y], m.positions[t.z], m.uv[0][t.x],
                          m.uv[0][t.y], m.uv[0][t.z], dpdu, dpdv);
}

TEST(TextureCoordinates, QuadCornersAreTheContractsAndTheTangentRunsAlongU) {
  const Mesh q = make_quad({0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0});
  ASSERT_EQ(q.uv[0].size(), 4u);
  EXPECT_EQ(q.uv[0][0], glm::vec2(0, 0));
  EXPECT_EQ(q.uv[0][1], glm::vec2(1, 0));
  EXPECT_EQ(q.uv[0][2], glm::vec2(1, 1));
  EXPECT_EQ(q.uv[0][3], glm::vec2(0, 1));
  ASSERT_EQ(q.tangents.size(), q.positions.size());
  for (const glm::vec4& t : q.tangents) {
    EXPECT_NEAR(t.x, 1.0f, 1e-6f);  // u runs from corner a to corner b: +x
    EXPECT_NEAR(t.y, 0.0f, 1e-6f);
    EXPECT_EQ(t.w, 1.0f);  // v runs up the quad, w cross(N, T) = cross(+z, +x) = +y
  }
  glm::vec3 dpdu, dpdv;
  derivatives(q, 0, dpdu, dpdv);
  EXPECT_EQ(dpdu, glm::vec3(2, 0, 0));  // the quad is 2 wide and 1 tall
  EXPECT_EQ(dpdv, glm::vec3(0, 1, 0));
}

// Seen from outside each face shows the whole image the right way round: u to the viewer's
// right, v up (+y on the sides, -z on top, +z underneath).
TEST(TextureCoordinates, BoxFacesShowTheImageUprightFromOutside) {
  const Mesh box = make_box({-1, -1, -1}, {1, 1, 1});
  ASSERT_EQ(box.uv[0].size(), 24u);
  ASSERT_EQ(box.tangents.size(), 24u);
  struct Face {
    glm::vec3 normal, right, up;
  };
  const Face faces[] = {
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
      {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
  };
  int matched = 0;
  for (std::size_t k = 0; k < box.triangles.size(); ++k) {
    const glm::uvec3 t = box.triangles[k];
    const glm::vec3 n = glm::normalize(glm::cross(box.positions[t.y] - box.positions[t.x],
                                                  box.positions[t.z] - box.positions[t.x]));
    for (const Face& f : faces) {
      if (glm::dot(n, f.normal) < 0.99f) continue;
      glm::vec3 dpdu, dpdv;
      derivatives(box, k, dpdu, dpdv);
      EXPECT_NEAR(glm::dot(glm::normalize(dpdu), f.right), 1.0f, 1e-6f) << k;
      EXPECT_NEAR(glm::dot(glm::normalize(dpdv), f.up), 1.0f, 1e-6f) << k;
      EXPECT_NEAR(glm::length(dpdu), 2.0f, 1e-6f);  // each face carries the image once
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(box.tangents[t[c]].w, 1.0f);
        EXPECT_NEAR(glm::dot(glm::vec3(box.tangents[t[c]]), f.right), 1.0f, 1e-6f);
      }
      ++matched;
    }
  }
  EXPECT_EQ(matched, 12);
}

TEST(TextureCoordinates, MirroredCoordinatesGiveHandednessMinusOne) {
  // u runs from b to a: the image is mirrored on this quad.
  Mesh q;
  q.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  q.triangles = {{0, 1, 2}, {0, 2, 3}};
  q.uv[0] = {{1, 0}, {0, 0}, {0, 1}, {1, 1}};
  generate_tangents(q);
  ASSERT_EQ(q.tangents.size(), 4u);
  for (const glm::vec4& t : q.tangents) {
    EXPECT_NEAR(t.x, -1.0f, 1e-6f);  // dP/du points to -x
    EXPECT_EQ(t.w, -1.0f);           // and w cross(N, T) = -cross(+z, -x) = +y = dP/dv
  }
}

TEST(TextureCoordinates, AMirroringTransformFlipsTheHandedness) {
  Mesh q = make_quad({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
  transform_mesh(q, glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)));
  for (const glm::vec4& t : q.tangents) {
    EXPECT_NEAR(t.x, -1.0f, 1e-6f);
    EXPECT_EQ(t.w, -1.0f);
  }
}

// A vertex shared by faces whose (u, v) run different ways gets a vertex per tangent.
TEST(TextureCoordinates, MikkTSpaceSplitsVerticesWhoseTangentsDiffer) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.uv[0] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};  // the second face's u runs towards -x... and up
  generate_tangents(m);
  EXPECT_EQ(m.tangents.size(), m.positions.size());
  EXPECT_GT(m.positions.size(), 4u);
  for (const glm::uvec3& t : m.triangles) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(glm::length(glm::vec3(m.tangents[t[c]])), 1.0f, 1e-5f);
  }
}

TEST(TextureCoordinates, TeapotPatchesCarryUnitTangentsAcrossTheirNormals) {
  BezierPatches patches;
  // One flat bicubic patch over the unit square in x, z (y up), rows along -z.
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      patches.points.emplace_back(j / 3.0f, 0.0f, -i / 3.0f);
    }
  }
  std::array<int, 16> patch;
  for (int k = 0; k < 16; ++k) patch[k] = k;
  patches.patches.push_back(patch);
  const Mesh m = tessellate_patches(patches, 4, true);
  ASSERT_EQ(m.uv[0].size(), m.positions.size());
  ASSERT_EQ(m.tangents.size(), m.positions.size());
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    EXPECT_NEAR(glm::length(glm::vec3(m.tangents[v])), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(glm::vec3(m.tangents[v]), m.normals[v]), 0.0f, 1e-6f);
    // (u, v) = (1 - t, 1 - s): u runs against the control rows' direction.
    EXPECT_NEAR(m.uv[0][v].x, 1.0f - m.positions[v].x, 1e-6f);
    EXPECT_NEAR(m.uv[0][v].y, 1.0f + m.positions[v].z, 1e-6f);
  }
}

}  // namespace
}  // namespace gloss

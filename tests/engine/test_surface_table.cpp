// The surface table's records: one per triangle, except a flat mesh whose triangles share one
// face normal, which keeps a single record for all of them (stride 0).
#include "engine/trace/surface_table.h"

#include <gtest/gtest.h>

#include "support/scene_fixtures.h"

namespace gloss {
namespace {

TEST(SurfaceTable, AWallHasOneRecordForBothTriangles) {
  Scene scene;
  test::add_quad(scene, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, 0);
  const SurfaceTable t = make_surface_table(scene);
  ASSERT_EQ(t.a[0].size(), 2u);  // the placeholder and the wall
  EXPECT_EQ(t.stride[0], 0u);
  EXPECT_EQ(t.record(0, 0), 1u);
  EXPECT_EQ(t.record(0, 1), 1u);
  EXPECT_EQ(glm::vec3(t.a[0][1], t.a[1][1], t.a[2][1]), glm::vec3(0, 0, 1));
  EXPECT_EQ(t.record(-1, 5), 0u);  // missed lanes
}

TEST(SurfaceTable, AFoldedQuadKeepsARecordPerTriangle) {
  Scene scene;
  test::add_sphere(scene, {0, 0, 0}, 1.0f, 0);
  // Corner d lifted off the plane of a, b, c: two different face normals.
  test::add_quad(scene, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 1}, 0);
  const SurfaceTable t = make_surface_table(scene);
  ASSERT_EQ(t.a[0].size(), 4u);  // placeholder, sphere, two triangles
  EXPECT_EQ(t.stride[1], 1u);
  EXPECT_EQ(t.record(0, 0), 1u);  // the sphere
  EXPECT_EQ(t.record(1, 0), 2u);
  EXPECT_EQ(t.record(1, 1), 3u);
  EXPECT_EQ(t.kind[0], kSphere);
  EXPECT_EQ(t.kind[1], kFlatTriangle);
}

}  // namespace
}  // namespace gloss

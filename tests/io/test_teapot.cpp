#include "io/model/teapot_reader.h"

#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "base/error.h"

namespace gloss {
namespace {

const std::string teapot_file = std::string(GLOSS_ASSETS_DIR) + "/models/utah-teapot.txt";

// Patch ranges of the shipped data (see the comments in utah-teapot.txt).
constexpr unsigned body_first = 4, body_end = 12;  // below the rim, above the bottom
constexpr unsigned knob_first = 20, lid_first = 24, lid_end = 28, bottom_first = 28;

unsigned vertices_per_patch(int level) {
  return (level + 1u) * (level + 1u);
}

// Triangles at level L: 2 L^2 per patch. Patches 20-23 (knob top) and 28-31 (bottom centre) have
// their first control row collapsed to one point, so the first row of cells loses one of its two
// triangles: L per such patch.
std::size_t expected_triangles(int level) {
  return 32u * 2 * level * level - 8u * level;
}

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "gloss_teapot_" + name;
  std::ofstream(path) << text;
  return path;
}

InputError load_error_of(const std::string& path) {
  try {
    load_bezier_patches(path);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no InputError for " << path;
  return InputError("", "");
}

// A one-patch file whose 16 indices are the given text.
std::string one_patch_file(const std::string& indices, const std::string& points) {
  return "# test\npatches 1\n" + indices + "\npoints 2\n" + points;
}

TEST(Teapot, ParsesShippedPatchFileAndConvertsToYUp) {
  const BezierPatches data = load_bezier_patches(teapot_file);
  ASSERT_EQ(data.patches.size(), 32u);
  ASSERT_EQ(data.points.size(), 290u);
  EXPECT_EQ(data.patches[0][15], 15);
  EXPECT_EQ(data.patches[31][0], 265);
  // Point 1 is "1.4 -0.784 2.4" (z-up): (x, y, z) -> (x, z, -y).
  EXPECT_EQ(data.points[1], glm::vec3(1.4f, 2.4f, 0.784f));
}

TEST(Teapot, ShippedPatchesScaleOnlyTheLidHorizontally) {
  const BezierPatches raw = load_bezier_patches(teapot_file);
  const BezierPatches& fitted = teapot_patches();
  // Point 204 "0.8 0.0 3.15" is a lid control point: x and file-y scaled by 1.077, height kept.
  const glm::vec3 lid = fitted.points[fitted.patches[20][4]];
  EXPECT_FLOAT_EQ(lid.x, 0.8f * 1.077f);
  EXPECT_FLOAT_EQ(lid.y, 3.15f);
  // Body points are untouched.
  EXPECT_EQ(fitted.points[fitted.patches[4][0]], raw.points[raw.patches[4][0]]);
  EXPECT_EQ(&fitted, &teapot_patches());  // loaded once
}

TEST(Teapot, LidMeetsTheRimWithoutAGap) {
  const int level = 8;
  const unsigned n = level + 1, per = vertices_per_patch(level);
  const Mesh mesh = tessellate_patches(teapot_patches(), level);
  // The rim's inner ring has radius 1.4; the lid's outer ring 1.3 * 1.077 = 1.4001 on the axes.
  // Between the axes the data's quarter circles (control ratio 0.56) bulge out by under 0.5 %.
  for (unsigned p = 0; p < 4; ++p) {
    for (unsigned j = 0; j < n; ++j) {
      const glm::vec3 rim = mesh.positions[p * per + j];  // first row of a rim patch
      EXPECT_NEAR(std::hypot(rim.x, rim.z), 1.4, 0.009);
      EXPECT_FLOAT_EQ(rim.y, 2.4f);
      const glm::vec3 lid = mesh.positions[(lid_first + p) * per + level * n + j];  // last row
      EXPECT_NEAR(std::hypot(lid.x, lid.z), 1.4, 0.009);
      EXPECT_FLOAT_EQ(lid.y, 2.4f);
    }
  }
}

TEST(Teapot, LevelOneDropsPoleTrianglesAndTheFlatSpoutTip) {
  // At level 1 the triangles join patch corners. The spout tip patches 18 and 19 have all four
  // corners on the line y = 2.4, z = 0 (points 173, 176, 193, 196), so both of theirs go too.
  const Mesh mesh = tessellate_patches(teapot_patches(), 1);
  EXPECT_EQ(mesh.positions.size(), 32u * 4);
  EXPECT_EQ(mesh.triangles.size(), expected_triangles(1) - 4);
}

TEST(Teapot, LevelFourHasExpectedTriangleCount) {
  const Mesh mesh = tessellate_patches(teapot_patches(), 4);
  EXPECT_EQ(mesh.positions.size(), 32u * 25);
  EXPECT_EQ(mesh.triangles.size(), 992u);  // 32 * 2 * 16 - 8 * 4
}

TEST(Teapot, TriangleCountFollowsLevelSquared) {
  for (int level : {2, 3, 7, 16, 64}) {
    const Mesh mesh = tessellate_patches(teapot_patches(), level);
    EXPECT_EQ(mesh.positions.size(), 32u * vertices_per_patch(level)) << level;
    EXPECT_EQ(mesh.triangles.size(), expected_triangles(level)) << level;
  }
}

TEST(Teapot, LevelOutsideOneToSixtyFourIsRejected) {
  EXPECT_THROW(tessellate_patches(teapot_patches(), 0), std::invalid_argument);
  EXPECT_THROW(tessellate_patches(teapot_patches(), 65), std::invalid_argument);
}

TEST(Teapot, BoundsMatchControlData) {
  const Mesh mesh = tessellate_patches(teapot_patches(), 16);
  glm::vec3 lo, hi;
  ASSERT_TRUE(mesh_bounds(mesh, lo, hi));
  // Exact extremes sit on patch corners or edges: the bottom centre (height 0), the knob top
  // (3.15), the widest body ring (radius 2) and the handle's outer corner (x = -3). The spout
  // tip's lip is inside its control hull, between its corner (3.3) and control point 199 (3.45).
  EXPECT_FLOAT_EQ(lo.y, 0.0f);
  EXPECT_FLOAT_EQ(hi.y, 3.15f);
  EXPECT_FLOAT_EQ(lo.z, -2.0f);
  EXPECT_FLOAT_EQ(hi.z, 2.0f);
  EXPECT_FLOAT_EQ(lo.x, -3.0f);
  EXPECT_GE(hi.x, 3.3f);
  EXPECT_LE(hi.x, 3.45f);
}

TEST(Teapot, NormalsAreUnitAndFinite) {
  for (int level : {1, 4, 16}) {
    const Mesh mesh = tessellate_patches(teapot_patches(), level);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (const glm::vec3& n : mesh.normals) {
      ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
      ASSERT_NEAR(glm::length(n), 1.0f, 1e-6f);
    }
  }
}

TEST(Teapot, NormalsPointOutOfBodyLidAndBottom) {
  const int level = 16;
  const unsigned per = vertices_per_patch(level);
  const Mesh mesh = tessellate_patches(teapot_patches(), level);
  for (unsigned v = 0; v < mesh.positions.size(); ++v) {
    const unsigned patch = v / per;
    const glm::vec3 p = mesh.positions[v], n = mesh.normals[v];
    const float radius = std::hypot(p.x, p.z);
    if (patch >= body_first && patch < body_end) {
      EXPECT_GT(glm::dot(n, glm::vec3(p.x, 0, p.z)), 0.0f) << v;  // away from the y axis
    } else if (patch >= lid_first && patch < lid_end) {
      EXPECT_GE(n.y, -1e-5f) << v;  // the lid's rim edge is vertical
      if (radius < 1.3f) {
        EXPECT_GT(n.y, 0.0f) << v;
      }
    } else if (patch >= bottom_first) {
      EXPECT_LE(n.y, 1e-5f) << v;  // where the bottom meets the body it is vertical
      if (radius < 1.4f) {
        EXPECT_LT(n.y, 0.0f) << v;
      }
    }
  }
  // The poles, where the derivative cross product vanishes, use the fallback: the knob top and
  // the bottom centre are flat, so their normals are straight up and straight down.
  EXPECT_GT(mesh.normals[knob_first * per].y, 0.999f);
  EXPECT_LT(mesh.normals[bottom_first * per].y, -0.999f);
}

// Cosine between each triangle's winding normal and the normals of its corners, smallest over
// the mesh.
float worst_winding_agreement(const Mesh& mesh) {
  float worst = 1.0f;
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::vec3 face = glm::normalize(glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                                                     mesh.positions[t.z] - mesh.positions[t.x]));
    for (unsigned k : {t.x, t.y, t.z}) worst = std::fmin(worst, glm::dot(face, mesh.normals[k]));
  }
  return worst;
}

TEST(Teapot, WindingAgreesWithSmoothNormals) {
  // Coarse levels cut across the rim's lip and the spout tip's curl, where a triangle spans more
  // than 90 degrees of turning; from level 6 on every corner is in the face's hemisphere.
  EXPECT_GT(worst_winding_agreement(tessellate_patches(teapot_patches(), 8)), 0.0f);
  // At level 32 a cell spans at most a few degrees of the body and about 20 degrees of the
  // spout tip's tight lip.
  EXPECT_GT(worst_winding_agreement(tessellate_patches(teapot_patches(), 32)), 0.9f);
}

TEST(Teapot, FlatTessellationHasNoNormalsAndTheSameTriangles) {
  const Mesh smooth = tessellate_patches(teapot_patches(), 5, true);
  const Mesh flat = tessellate_patches(teapot_patches(), 5, false);
  EXPECT_FALSE(flat.smooth());
  EXPECT_EQ(flat.positions, smooth.positions);
  EXPECT_EQ(flat.triangles, smooth.triangles);
}

TEST(Teapot, MissingFileIsAnInputErrorNamingIt) {
  const InputError error = load_error_of("/nonexistent/teapot.txt");
  EXPECT_EQ(error.file(), "/nonexistent/teapot.txt");
  EXPECT_NE(std::string(error.what()).find("/nonexistent/teapot.txt"), std::string::npos);
}

TEST(Teapot, MalformedFilesReportFileAndLine) {
  const std::string sixteen = "0 1 0 1 0 1 0 1 0 1 0 1 0 1 0 1";
  const std::string two_points = "0 0 0\n1 0 0\n";
  struct Case {
    std::string name, text;
    int line;
  } cases[] = {
      {"short_patch", one_patch_file("0 1 2", two_points), 3},
      {"bad_index", one_patch_file("0 1 0 1 0 1 0 1 0 1 0 1 0 1 0 x", two_points), 3},
      {"index_range", one_patch_file("0 1 0 1 0 1 0 1 0 1 0 1 0 1 0 2", two_points), 3},
      {"bad_point", one_patch_file(sixteen, "0 0 0\n1 zero 0\n"), 6},
      {"truncated", one_patch_file(sixteen, "0 0 0\n"), 5},
      {"bad_header", "patches one\n", 1},
      {"unknown_section", one_patch_file(sixteen, two_points) + "normals 1\n", 7},
  };
  for (const Case& c : cases) {
    const std::string path = write_temp(c.name + ".txt", c.text);
    const InputError error = load_error_of(path);
    EXPECT_EQ(error.file(), path) << c.name;
    EXPECT_EQ(error.line(), c.line) << c.name << ": " << error.what();
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << c.name;
  }
}

TEST(Teapot, FileWithoutPointsIsAnInputError) {
  const std::string path =
      write_temp("no_points.txt", "patches 1\n0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n");
  EXPECT_THROW(load_bezier_patches(path), InputError);
}

}  // namespace
}  // namespace gloss

#include "io/obj_loader.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "base/error.h"

namespace gloss {
namespace {

std::string obj_file(const std::string& name) {
  return std::string(GLOSS_TEST_DATA_DIR) + "/obj/" + name;
}

InputError load_error_of(const std::string& path) {
  try {
    load_obj(path);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no InputError for " << path;
  return InputError("", "");
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

glm::vec3 face_normal(const Mesh& mesh, const glm::uvec3& t) {
  return glm::normalize(glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                                   mesh.positions[t.z] - mesh.positions[t.x]));
}

TEST(ObjLoader, CubeWithNormalsHasTwelveTrianglesOnTwentyFourVertices) {
  const ObjModel model = load_obj(obj_file("cube.obj"));
  EXPECT_TRUE(model.warnings.empty());
  ASSERT_EQ(model.parts.size(), 1u);
  const Mesh& mesh = model.parts[0].mesh;
  EXPECT_EQ(model.parts[0].material_name, "red");
  EXPECT_EQ(mesh.triangles.size(), 12u);
  // 6 faces x 4 corners: each corner is a distinct (position, normal) pair.
  EXPECT_EQ(mesh.positions.size(), 24u);
  ASSERT_TRUE(mesh.smooth());
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::vec3 face = face_normal(mesh, t);
    for (unsigned k : {t.x, t.y, t.z}) EXPECT_EQ(mesh.normals[k], face);  // file normals, outward
  }
}

TEST(ObjLoader, FlatCubeSharesItsEightCorners) {
  const ObjModel model = load_obj(obj_file("cube.obj"), false);
  ASSERT_EQ(model.parts.size(), 1u);
  EXPECT_FALSE(model.parts[0].mesh.smooth());
  EXPECT_EQ(model.parts[0].mesh.positions.size(), 8u);
  EXPECT_EQ(model.parts[0].mesh.triangles.size(), 12u);
}

TEST(ObjLoader, MaterialConstantsEqualTheMtlValues) {
  const ObjModel model = load_obj(obj_file("cube.obj"));
  ASSERT_EQ(model.material_names.size(), 2u);
  ASSERT_EQ(model.materials.size(), 2u);
  EXPECT_EQ(model.material_names[0], "red");
  EXPECT_EQ(model.material_names[1], "glow");
  const Material& red = model.materials[0];
  EXPECT_EQ(red.ambient, glm::vec3(0.1f, 0.0f, 0.0f));
  EXPECT_EQ(red.diffuse, glm::vec3(0.7f, 0.1f, 0.1f));
  EXPECT_EQ(red.specular, glm::vec3(0.5f, 0.5f, 0.5f));
  EXPECT_EQ(red.emission, glm::vec3(0.0f));
  EXPECT_EQ(red.shininess, 32.0f);
  EXPECT_TRUE(red.preset.empty());
  const Material& glow = model.materials[1];
  EXPECT_EQ(glow.ambient, glm::vec3(0.0f));
  EXPECT_EQ(glow.diffuse, glm::vec3(0.2f, 0.3f, 0.4f));
  EXPECT_EQ(glow.specular, glm::vec3(0.25f));
  EXPECT_EQ(glow.emission, glm::vec3(1.0f, 0.5f, 0.25f));
  EXPECT_EQ(glow.shininess, 96.5f);
}

TEST(ObjLoader, MaterialGroupsBecomePartsInFileOrder) {
  const ObjModel model = load_obj(obj_file("two_materials.obj"));
  ASSERT_EQ(model.parts.size(), 2u);
  EXPECT_EQ(model.parts[0].material_name, "red");  // groups 1 and 3
  EXPECT_EQ(model.parts[0].mesh.triangles.size(), 2u);
  EXPECT_EQ(model.parts[0].mesh.positions.size(), 4u);
  EXPECT_EQ(model.parts[1].material_name, "glow");  // the quad of group 2
  EXPECT_EQ(model.parts[1].mesh.triangles.size(), 2u);
  // A flat sheet in z = 0 wound counter-clockwise from +z: every computed normal is +z.
  for (const ObjPart& part : model.parts) {
    for (const glm::vec3& n : part.mesh.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
  }
}

TEST(ObjLoader, MissingNormalsAreAreaWeightedFaceAverages) {
  const ObjModel model = load_obj(obj_file("tetra_no_normals.obj"));
  ASSERT_EQ(model.parts.size(), 1u);
  EXPECT_TRUE(model.parts[0].material_name.empty());
  const Mesh& mesh = model.parts[0].mesh;
  ASSERT_EQ(mesh.positions.size(), 4u);
  ASSERT_TRUE(mesh.smooth());
  // Faces: three right triangles of area 1/2 on the coordinate planes (normals -x, -y, -z) and
  // one of area sqrt(3)/2 with normal (1, 1, 1)/sqrt(3). Weighted by area, the origin gets
  // -(1, 1, 1)/sqrt(3); X = (1, 0, 0) gets -z/2 - y/2 + (1, 1, 1)/2 = (1/2, 0, 0), i.e. +x.
  const float third = 1.0f / std::sqrt(3.0f);
  for (unsigned v = 0; v < 4; ++v) {
    const glm::vec3 p = mesh.positions[v], n = mesh.normals[v];
    const glm::vec3 expected = p == glm::vec3(0) ? glm::vec3(-third) : p;
    EXPECT_NEAR(glm::length(n - expected), 0.0f, 1e-6f) << v;
  }
}

TEST(ObjLoader, DegenerateTrianglesAreDroppedWithAWarning) {
  const std::string path = obj_file("degenerate.obj");
  const ObjModel model = load_obj(path);
  ASSERT_EQ(model.parts.size(), 1u);
  EXPECT_EQ(model.parts[0].mesh.triangles.size(), 4u);
  EXPECT_EQ(model.parts[0].mesh.positions.size(), 4u);  // vertex 5 served only a dropped triangle
  ASSERT_EQ(model.warnings.size(), 1u);
  EXPECT_EQ(model.warnings[0], path + ": dropped 2 degenerate triangles");
}

TEST(ObjLoader, MissingMaterialLibraryWarnsAndUsesNoMaterial) {
  const std::string path = obj_file("missing_mtl.obj");
  const ObjModel model = load_obj(path);
  ASSERT_EQ(model.parts.size(), 1u);
  EXPECT_TRUE(model.parts[0].material_name.empty());
  EXPECT_TRUE(model.materials.empty());
  ASSERT_EQ(model.warnings.size(), 2u);
  EXPECT_TRUE(contains(model.warnings[0], path + ":2:")) << model.warnings[0];
  EXPECT_TRUE(contains(model.warnings[1], path + ":6:")) << model.warnings[1];
  EXPECT_TRUE(contains(model.warnings[1], "'red'")) << model.warnings[1];
}

TEST(ObjLoader, BadFilesThrowInputErrorNamingTheFileAndLine) {
  const struct {
    const char* name;
    int line;  // 0: no line applies
  } cases[] = {
      {"garbage.obj", 0},        {"no_faces.obj", 0},
      {"out_of_range.obj", 5},   {"relative_out_of_range.obj", 5},
      {"zero_index.obj", 4},     {"bad_vertex.obj", 2},
      {"does_not_exist.obj", 0},
  };
  for (const auto& c : cases) {
    const std::string path = obj_file(c.name);
    const InputError error = load_error_of(path);
    EXPECT_EQ(error.file(), path) << c.name;
    EXPECT_EQ(error.line(), c.line) << c.name << ": " << error.what();
    EXPECT_TRUE(contains(error.what(), path)) << error.what();
  }
}

TEST(ObjLoader, OutOfRangeIndexMessageNamesTheIndex) {
  const InputError error = load_error_of(obj_file("out_of_range.obj"));
  EXPECT_TRUE(contains(error.message(), "vertex index 7")) << error.what();
}

TEST(ObjLoader, NegativeMtlColourIsAnInputErrorNamingTheMtl) {
  const InputError error = load_error_of(obj_file("bad_mtl.obj"));
  EXPECT_EQ(error.file(), obj_file("bad.mtl"));
  EXPECT_TRUE(contains(error.what(), "Kd")) << error.what();
  EXPECT_TRUE(contains(error.what(), "negative")) << error.what();  // the material's name
}

}  // namespace
}  // namespace gloss

#include "io/model/model_loader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "base/error.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

std::string obj_file(const std::string& name) {
  return std::string(GLOSS_TEST_DATA_DIR) + "/obj/" + name;
}

std::string write_file(const ScratchFolder& folder, const std::string& name,
                       const std::string& text) {
  const std::string path = folder.file(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

InputError load_error_of(const std::string& path) {
  try {
    load_model(path);
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

double area(const Mesh& mesh) {
  double sum = 0.0;
  for (const glm::uvec3& t : mesh.triangles) {
    sum += 0.5 * glm::length(glm::cross(glm::dvec3(mesh.positions[t.y] - mesh.positions[t.x]),
                                        glm::dvec3(mesh.positions[t.z] - mesh.positions[t.x])));
  }
  return sum;
}

// The unit cube's six quads, wound counter-clockwise from outside, without normals.
const char* const kCubeWithoutNormals =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 5 8 4\nf 2 3 7 6\nf 1 2 6 5\nf 4 8 7 3\nf 1 4 3 2\nf 5 6 7 8\n";

// A unit sphere of 16 segments by 8 rings without normals (neighbouring faces meet at 22.5
// degrees at most, under the 30 degree default crease angle); prefix goes before the faces.
std::string sphere_obj(const std::string& prefix) {
  const double pi = std::acos(-1.0);
  std::string text = "v 0 1 0\n";
  for (int ring = 1; ring < 8; ++ring) {
    for (int seg = 0; seg < 16; ++seg) {
      const double theta = pi * ring / 8, phi = 2 * pi * seg / 16;
      text += "v " + std::to_string(std::sin(theta) * std::cos(phi)) + " " +
              std::to_string(std::cos(theta)) + " " +
              std::to_string(-std::sin(theta) * std::sin(phi)) + "\n";
    }
  }
  text += "v 0 -1 0\n" + prefix;
  auto at = [](int ring, int seg) { return std::to_string(2 + (ring - 1) * 16 + seg % 16); };
  for (int seg = 0; seg < 16; ++seg) text += "f 1 " + at(1, seg) + " " + at(1, seg + 1) + "\n";
  for (int ring = 1; ring < 7; ++ring) {
    for (int seg = 0; seg < 16; ++seg) {
      text += "f " + at(ring, seg) + " " + at(ring + 1, seg) + " " + at(ring + 1, seg + 1) + " " +
              at(ring, seg + 1) + "\n";
    }
  }
  for (int seg = 0; seg < 16; ++seg) text += "f " + at(7, seg) + " 114 " + at(7, seg + 1) + "\n";
  return text;
}

TEST(ModelLoader, CubeWithNormalsHasTwelveTrianglesOnTwentyFourVertices) {
  const Model model = load_model(obj_file("cube.obj"));
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

TEST(ModelLoader, NotSmoothDropsTheNormalsAndSharesTheEightCorners) {
  const Model model = load_model(obj_file("cube.obj"), {false, kDefaultCreaseAngle});
  ASSERT_EQ(model.parts.size(), 1u);
  EXPECT_FALSE(model.parts[0].mesh.smooth());
  EXPECT_EQ(model.parts[0].mesh.positions.size(), 8u);
  EXPECT_EQ(model.parts[0].mesh.triangles.size(), 12u);
}

TEST(ModelLoader, MaterialConstantsEqualTheMtlValues) {
  const Model model = load_model(obj_file("cube.obj"));
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

TEST(ModelLoader, MaterialGroupsBecomeParts) {
  const Model model = load_model(obj_file("two_materials.obj"));
  ASSERT_EQ(model.parts.size(), 2u);
  EXPECT_EQ(model.parts[0].material_name, "red");  // groups 1 and 3
  EXPECT_EQ(model.parts[0].mesh.triangles.size(), 2u);
  EXPECT_EQ(model.parts[0].mesh.positions.size(), 4u);
  EXPECT_EQ(model.parts[1].material_name, "glow");  // the quad of group 2
  EXPECT_EQ(model.parts[1].mesh.triangles.size(), 2u);
  // A flat sheet in z = 0 wound counter-clockwise from +z: every computed normal is +z.
  for (const ModelPart& part : model.parts) {
    ASSERT_TRUE(part.mesh.smooth());
    for (const glm::vec3& n : part.mesh.normals)
      EXPECT_NEAR(glm::length(n - glm::vec3(0, 0, 1)), 0, 1e-6f);
  }
}

TEST(ModelLoader, CubeWithoutNormalsStaysABox) {
  const ScratchFolder folder;
  const Model model = load_model(write_file(folder, "box.obj", kCubeWithoutNormals));
  ASSERT_EQ(model.parts.size(), 1u);
  const Mesh& mesh = model.parts[0].mesh;
  EXPECT_EQ(mesh.triangles.size(), 12u);
  ASSERT_TRUE(mesh.smooth());
  EXPECT_EQ(mesh.positions.size(), 24u);  // 90 degree edges exceed the crease angle: split
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::vec3 face = face_normal(mesh, t);
    for (unsigned k : {t.x, t.y, t.z}) EXPECT_NEAR(glm::length(mesh.normals[k] - face), 0, 1e-6f);
  }
}

TEST(ModelLoader, CreaseAngleAboveNinetyRoundsTheBox) {
  const ScratchFolder folder;
  const Model model = load_model(write_file(folder, "box.obj", kCubeWithoutNormals), {true, 180});
  const Mesh& mesh = model.parts[0].mesh;
  ASSERT_TRUE(mesh.smooth());
  EXPECT_EQ(mesh.positions.size(), 8u);
  // Every corner averages its three faces' normals: the diagonal through the cube's centre.
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::vec3 diagonal = glm::normalize(mesh.positions[v] - glm::vec3(0.5f));
    EXPECT_NEAR(glm::length(mesh.normals[v] - diagonal), 0, 1e-6f) << v;
  }
}

TEST(ModelLoader, SphereWithoutNormalsIsSmoothedAcrossItsShallowEdges) {
  const ScratchFolder folder;
  const Model model = load_model(write_file(folder, "sphere.obj", sphere_obj("")));
  const Mesh& mesh = model.parts[0].mesh;
  ASSERT_TRUE(mesh.smooth());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    // Averaged neighbouring face normals lie within 8 degrees of the radial direction; a face
    // normal is up to about 16 degrees off it at a quad's corner (cos 16 = 0.96).
    EXPECT_GT(glm::dot(mesh.normals[v], glm::normalize(mesh.positions[v])), 0.99f) << v;
  }
}

TEST(ModelLoader, SmoothingGroupsOffGiveFlatFaces) {
  const ScratchFolder folder;
  const Model model = load_model(write_file(folder, "sphere.obj", sphere_obj("s off\n")));
  EXPECT_FALSE(model.parts[0].mesh.smooth());
  const Model on = load_model(write_file(folder, "sphere1.obj", sphere_obj("s 1\n")));
  EXPECT_TRUE(on.parts[0].mesh.smooth());
}

TEST(ModelLoader, ConcavePolygonWithBridgedHoleGivesSixtyFourTriangles) {
  const std::string path = "/usr/share/assimp/models/OBJ/concave_polygon.obj";
  if (!std::ifstream(path)) GTEST_SKIP() << "assimp-testmodels not installed";
  const Model model = load_model(path);
  ASSERT_EQ(model.parts.size(), 1u);
  EXPECT_EQ(model.parts[0].mesh.triangles.size(), 64u);  // 66 corners - 2
  // The shoelace area of the 66-corner polygon in its plane x = -1.146 (the bridge's two edges
  // cancel, so it is the outer ring's area minus the hole's), computed from the file's vertices.
  EXPECT_NEAR(area(model.parts[0].mesh), 0.2454966872, 1e-6);
}

TEST(ModelLoader, CarriageReturnAfterVNeverReadsOutOfBounds) {
  // Found by fuzzing the old loader: its pre-scan counted 4 vertices where the OBJ reader saw 3,
  // so "-4" passed its range check and read before the array.
  const ScratchFolder folder;
  const std::string path =
      write_file(folder, "cr.obj", "v 1 0 0\nv 0 0 0\nv\r 1 0 0\nv 0 1 0\nf -1 -2 -4\n");
  try {
    const Model model = load_model(path);
    for (const ModelPart& part : model.parts) {
      for (const glm::uvec3& t : part.mesh.triangles) {
        for (int k = 0; k < 3; ++k) EXPECT_LT(t[k], part.mesh.positions.size());
      }
    }
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), path);
  }
}

// Two files of assimp-testmodels that tinyobjloader and assimp both accept.
TEST(ModelLoader, NumberFormatsLoadsItsOneDegenerateTriangleAsAnEmptyPartWithAWarning) {
  const std::string path = "/usr/share/assimp/models/OBJ/number_formats.obj";
  if (!std::ifstream(path)) GTEST_SKIP() << "assimp-testmodels not installed";
  // f 1 2 4 joins (0, 0, 0), (1, 2, 3) and (-1, -2, -3): collinear, so nothing is left to draw,
  // which is a warning, never an error (docs/scene-format.md).
  const Model model = load_model(path);
  ASSERT_EQ(model.parts.size(), 1u);
  EXPECT_TRUE(model.parts[0].mesh.triangles.empty());
  ASSERT_EQ(model.warnings.size(), 1u);
  EXPECT_EQ(model.warnings[0], path + ": dropped 1 degenerate triangles");
}

TEST(ModelLoader, MalformedTwoSkipsItsEmptyFaceAndKeepsTheOtherFive) {
  const std::string path = "/usr/share/assimp/models/invalid/malformed2.obj";
  if (!std::ifstream(path)) GTEST_SKIP() << "assimp-testmodels not installed";
  const Model model = load_model(path);  // a bare "f" line, then five quads of a unit cube
  ASSERT_EQ(model.parts.size(), 1u);
  EXPECT_EQ(model.parts[0].mesh.triangles.size(), 10u);
  EXPECT_NEAR(area(model.parts[0].mesh), 5.0, 1e-6);
}

// A glTF metallic-roughness material comes in as the Phong lobe fitted to it when that is
// closer than assimp's rule (kd = base, ks = mix(0.04, base, metallic) (1 - roughness),
// Ns = 1000 (1 - roughness)^2), both errors measured and said in a note.
TEST(ModelLoader, GltfMetallicRoughnessComesInAsTheFittedPhong) {
  const std::string path = "/usr/share/assimp/models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf";
  if (!std::ifstream(path)) GTEST_SKIP() << "assimp-testmodels not installed";
  const Model model = load_model(path);
  // "Simple_Base": base colour (0.5, 0.02, 0.01), metallic 0, roughness 0.44.
  const auto it =
      std::find(model.material_names.begin(), model.material_names.end(), "Simple_Base");
  ASSERT_NE(it, model.material_names.end());
  const std::size_t i = static_cast<std::size_t>(it - model.material_names.begin());
  const Material& m = model.materials[i];
  const ModelFileMaterial& f = model.file_materials[i];
  EXPECT_TRUE(f.fitted);
  EXPECT_GT(f.fit_residual, 0.0);
  EXPECT_LT(f.fit_residual, f.rule_residual);
  // A dielectric: a grey highlight (F0 = 0.04 in every channel; the channels differ only as
  // the Fresnel-weighted diffuse shares the lobe: within 2 %), the base colour's order in kd.
  EXPECT_NEAR(m.specular.x, m.specular.y, 0.02 * m.specular.x);
  EXPECT_NEAR(m.specular.y, m.specular.z, 0.02 * m.specular.y);
  EXPECT_GT(m.diffuse.x, 10.0f * m.diffuse.y);
  EXPECT_GT(m.diffuse.y, m.diffuse.z);
  EXPECT_EQ(m.ambient, m.diffuse);
  EXPECT_EQ(m.emission, glm::vec3(0.0f));
  const std::string note = "material 'Simple_Base': metallic-roughness as the fitted Phong";
  EXPECT_TRUE(std::any_of(model.notes.begin(), model.notes.end(),
                          [&](const std::string& n) { return n.rfind(note, 0) == 0; }));
}

TEST(ModelLoader, DegenerateTrianglesAreDroppedWithAWarning) {
  const std::string path = obj_file("degenerate.obj");
  const Model model = load_model(path);
  ASSERT_EQ(model.parts.size(), 1u);
  EXPECT_EQ(model.parts[0].mesh.triangles.size(), 4u);
  ASSERT_EQ(model.warnings.size(), 1u);
  EXPECT_EQ(model.warnings[0], path + ": dropped 2 degenerate triangles");
}

TEST(ModelLoader, MissingMaterialLibraryGivesTheUsedNameReadersDefaults) {
  // As assimp reads it: `usemtl red` without a library makes a material "red" with the MTL
  // reader's defaults (Ka 0, Kd 0.6, Ks 0, Ke 0, Ns 0).
  const Model model = load_model(obj_file("missing_mtl.obj"));
  ASSERT_EQ(model.parts.size(), 1u);
  EXPECT_EQ(model.parts[0].material_name, "red");
  ASSERT_EQ(model.materials.size(), 1u);
  EXPECT_EQ(model.materials[0].ambient, glm::vec3(0.0f));
  EXPECT_EQ(model.materials[0].diffuse, glm::vec3(0.6f));
  EXPECT_EQ(model.materials[0].specular, glm::vec3(0.0f));
  EXPECT_EQ(model.materials[0].emission, glm::vec3(0.0f));
  EXPECT_EQ(model.materials[0].shininess, 0.0f);
}

TEST(ModelLoader, BadFilesThrowInputErrorNamingTheFile) {
  for (const char* name : {"garbage.obj", "no_faces.obj", "out_of_range.obj",
                           "relative_out_of_range.obj", "zero_index.obj", "does_not_exist.obj",
                           // "v 1 zero 0": assimp skips a vertex with two numbers, so the face's
                           // third index is out of range
                           "bad_vertex.obj"}) {
    const std::string path = obj_file(name);
    const InputError error = load_error_of(path);
    EXPECT_EQ(error.file(), path) << name;
    EXPECT_TRUE(contains(error.what(), path)) << error.what();
    EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << error.what();
  }
}

TEST(ModelLoader, UnknownExtensionIsRefusedByName) {
  const ScratchFolder folder;
  const InputError error = load_error_of(write_file(folder, "model.3ds", "x"));
  EXPECT_TRUE(contains(error.message(), "'.3ds'")) << error.what();
}

TEST(ModelLoader, NegativeMtlColourIsAnInputErrorNamingTheMaterial) {
  const InputError error = load_error_of(obj_file("bad_mtl.obj"));
  EXPECT_EQ(error.file(), obj_file("bad_mtl.obj"));
  EXPECT_TRUE(contains(error.what(), "Kd")) << error.what();
  EXPECT_TRUE(contains(error.what(), "negative")) << error.what();  // the material's name
}

}  // namespace
}  // namespace gloss

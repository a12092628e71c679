// Scene files that load: shipped scenes, documented defaults, presets, geometry placement, OBJ
// meshes with and without their MTL, and the exact save -> load round trip.
#include "io/scene/scene_loader.h"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "base/error.h"
#include "io/material/preset_table.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

const char* const kShippedScenes[] = {"spheres", "cornell", "cornell-teapot",
                                      "teapot",  "presets", "studio-metals"};

std::string shipped_scene(const std::string& name) {
  return std::string(GLOSS_ASSETS_DIR) + "/scenes/" + name + ".json";
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A unit right triangle in the xy plane with one MTL material, and a second material group.
const char* const kTwoPartObj = R"(mtllib parts.mtl
v 0 0 0
v 1 0 0
v 0 1 0
v 0 0 1
usemtl red
f 1 2 3
usemtl blue
f 1 2 4
)";
const char* const kTwoPartMtl = R"(newmtl red
Ka 0.1 0 0
Kd 0.7 0 0
Ks 0 0 0
Ns 10
newmtl blue
Ka 0 0 0.1
Kd 0 0 0.7
Ks 0.5 0.5 0.5
Ns 20
)";

void expect_meshes_equal(const Object& a, const Object& b) {
  ASSERT_EQ(a.mesh == nullptr, b.mesh == nullptr) << a.name;
  if (!a.mesh) return;
  EXPECT_EQ(a.mesh->positions, b.mesh->positions) << a.name;
  EXPECT_EQ(a.mesh->normals, b.mesh->normals) << a.name;
  EXPECT_EQ(a.mesh->triangles, b.mesh->triangles) << a.name;
}

void expect_scenes_equal(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.camera, b.camera);
  EXPECT_EQ(a.background, b.background);
  EXPECT_EQ(a.ambient, b.ambient);
  EXPECT_EQ(a.lights, b.lights);
  EXPECT_EQ(a.material_names, b.material_names);
  EXPECT_EQ(a.materials, b.materials);
  const RenderSettings &ra = a.render, &rb = b.render;
  EXPECT_EQ(ra.width, rb.width);
  EXPECT_EQ(ra.height, rb.height);
  EXPECT_EQ(ra.spp, rb.spp);
  EXPECT_EQ(ra.model, rb.model);
  EXPECT_EQ(ra.shadows, rb.shadows);
  EXPECT_EQ(ra.energy_normalize, rb.energy_normalize);
  EXPECT_EQ(ra.srgb, rb.srgb);
  EXPECT_EQ(ra.seed, rb.seed);
  EXPECT_EQ(ra.pow, rb.pow);
  ASSERT_EQ(a.objects.size(), b.objects.size());
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    const Object &x = a.objects[i], &y = b.objects[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.type, y.type) << x.name;
    EXPECT_EQ(x.material, y.material) << x.name;
    EXPECT_EQ(x.center, y.center) << x.name;
    EXPECT_EQ(x.radius, y.radius) << x.name;
    for (int k = 0; k < 4; ++k) EXPECT_EQ(x.params.quad[k], y.params.quad[k]) << x.name;
    EXPECT_EQ(x.params.box_min, y.params.box_min) << x.name;
    EXPECT_EQ(x.params.box_max, y.params.box_max) << x.name;
    EXPECT_EQ(x.params.file, y.params.file) << x.name;
    EXPECT_EQ(x.params.group, y.params.group) << x.name;
    EXPECT_EQ(x.params.position, y.params.position) << x.name;
    EXPECT_EQ(x.params.scale, y.params.scale) << x.name;
    EXPECT_EQ(x.params.rotate_y, y.params.rotate_y) << x.name;
    EXPECT_EQ(x.params.tessellation, y.params.tessellation) << x.name;
    EXPECT_EQ(x.params.smooth, y.params.smooth) << x.name;
    EXPECT_EQ(x.params.crease_angle, y.params.crease_angle) << x.name;
    expect_meshes_equal(x, y);
  }
}

void expect_near3(const glm::vec3& actual, const glm::vec3& expected, float tolerance) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(actual[k], expected[k], tolerance) << "axis " << k;
}

TEST(SceneLoader, EveryShippedSceneLoadsWithoutWarnings) {
  for (const char* name : kShippedScenes) {
    std::vector<std::string> warnings;
    Scene scene;
    ASSERT_NO_THROW(scene = load_scene(shipped_scene(name), &warnings)) << name;
    EXPECT_TRUE(warnings.empty()) << name << ": " << (warnings.empty() ? "" : warnings[0]);
    EXPECT_FALSE(scene.objects.empty()) << name;
    // One point light each, but studio-metals: lit by its environment alone.
    if (std::string(name) == "studio-metals") {
      EXPECT_TRUE(scene.lights.empty()) << name;
      EXPECT_TRUE(scene.environment.present()) << name;
    } else {
      EXPECT_EQ(scene.lights.size(), 1u) << name;
    }
  }
}

TEST(SceneLoader, CornellSceneHasTheSeedReportsCameraLightAndFifteenQuads) {
  const Scene scene = load_scene(shipped_scene("cornell"));
  EXPECT_EQ(scene.camera.eye, glm::vec3(0.0f, 0.0f, 3.001f));
  EXPECT_EQ(scene.camera.fov_y, 53.13f);
  EXPECT_EQ(scene.lights[0].position, glm::vec3(0.0f, 0.5f, 0.7f));
  EXPECT_EQ(scene.lights[0].diffuse, glm::vec3(2.0f));
  EXPECT_EQ(scene.objects.size(), 15u);  // 5 walls + 2 blocks x (4 sides + top)
  const int blocks = find_material(scene, "blocks");
  ASSERT_GE(blocks, 0);
  EXPECT_EQ(scene.materials[blocks].preset, "silver");
  EXPECT_EQ(scene.materials[blocks].shininess, 50.0f);
  EXPECT_EQ(scene.render.width, 512);
  EXPECT_EQ(scene.render.height, 512);
}

TEST(SceneLoader, PresetsSceneIsA6By4GridInTableOrder) {
  const Scene scene = load_scene(shipped_scene("presets"));
  const std::vector<Preset>& table = preset_table();
  ASSERT_EQ(scene.objects.size(), 24u);
  ASSERT_EQ(table.size(), 24u);
  for (std::size_t i = 0; i < 24; ++i) {
    const Object& sphere = scene.objects[i];
    EXPECT_EQ(sphere.name, table[i].name);
    EXPECT_EQ(scene.material_names[sphere.material], table[i].name);
    EXPECT_EQ(scene.materials[sphere.material], table[i].material);
    // Row-major from the top left: x grows along a row, y falls from row to row.
    EXPECT_EQ(sphere.center.x, -5.0f + 2.0f * static_cast<float>(i % 6));
    EXPECT_EQ(sphere.center.y, 3.0f - 2.0f * static_cast<float>(i / 6));
  }
}

TEST(SceneLoader, MinimalSceneGetsTheDocumentedDefaults) {
  const Scene scene = parse_scene(R"({"objects": []})", "minimal.json");
  EXPECT_EQ(scene.camera.eye, glm::vec3(0.0f, 0.0f, 5.0f));
  EXPECT_EQ(scene.camera.target, glm::vec3(0.0f));
  EXPECT_EQ(scene.camera.up, glm::vec3(0.0f, 1.0f, 0.0f));
  EXPECT_EQ(scene.camera.fov_y, 40.0f);
  EXPECT_EQ(scene.background, glm::vec3(0.0f));
  EXPECT_EQ(scene.ambient, glm::vec3(0.2f));
  EXPECT_TRUE(scene.lights.empty());
  EXPECT_TRUE(scene.materials.empty());
  EXPECT_EQ(scene.render.width, 640);
  EXPECT_EQ(scene.render.height, 480);
  EXPECT_EQ(scene.render.spp, 1);
  EXPECT_EQ(scene.render.model, ShadingModel::phong);
  EXPECT_TRUE(scene.render.shadows);
  EXPECT_FALSE(scene.render.energy_normalize);
  EXPECT_FALSE(scene.render.srgb);
  EXPECT_EQ(scene.render.seed, 0u);
  EXPECT_EQ(scene.render.pow, PowMode::exact);
  EXPECT_EQ(scene.path, "minimal.json");
}

TEST(SceneLoader, LightAndObjectDefaultsApplyToOmittedFields) {
  const Scene scene = parse_scene(R"({
    "lights": [{"position": [1, 2, 3]}],
    "materials": {"m": {"diffuse": [0.5, 0.5, 0.5]}},
    "objects": [
      {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"},
      {"type": "teapot", "material": "m"}
    ]})",
                                  "defaults.json");
  const PointLight& light = scene.lights.at(0);
  EXPECT_EQ(light.ambient, glm::vec3(0.0f));
  EXPECT_EQ(light.diffuse, glm::vec3(1.0f));
  EXPECT_EQ(light.specular, glm::vec3(1.0f));
  EXPECT_EQ(light.attenuation, glm::vec3(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(scene.objects.at(0).name, "sphere0");
  const Object& teapot = scene.objects.at(1);
  EXPECT_EQ(teapot.name, "teapot1");
  EXPECT_EQ(teapot.params.tessellation, 8);
  EXPECT_TRUE(teapot.params.smooth);
  EXPECT_EQ(teapot.params.scale, glm::vec3(1.0f));
  // tessellate_patches makes 2 * level^2 triangles per patch; the poles' degenerate ones go.
  ASSERT_TRUE(teapot.mesh);
  EXPECT_LE(teapot.mesh->triangles.size(), 32u * 2u * 8u * 8u);
  EXPECT_GT(teapot.mesh->triangles.size(), 32u * 2u * 8u * 8u * 9u / 10u);
}

TEST(SceneLoader, PresetMaterialTakesOverridesAndKeepsTheRestOfThePreset) {
  const Scene scene = parse_scene(R"({
    "materials": {"softer": {"preset": "gold", "shininess": 12}},
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "softer"}]})",
                                  "preset.json");
  const Material& m = scene.materials.at(0);
  // Gold's row of assets/materials/opengl-vrml.csv.
  EXPECT_EQ(m.ambient, glm::vec3(0.24725f, 0.1995f, 0.0745f));
  EXPECT_EQ(m.diffuse, glm::vec3(0.75164f, 0.60648f, 0.22648f));
  EXPECT_EQ(m.specular, glm::vec3(0.628281f, 0.555802f, 0.366065f));
  EXPECT_EQ(m.shininess, 12.0f);
  EXPECT_EQ(m.preset, "gold");
}

TEST(SceneLoader, BoxRotatesAboutItsOwnCentreThenMoves) {
  const Scene scene = parse_scene(R"({
    "materials": {"m": {}},
    "objects": [{"type": "box", "min": [0, 0, 0], "max": [2, 1, 1], "rotate_y": 90,
                 "position": [10, 0, 0], "material": "m"}]})",
                                  "box.json");
  glm::vec3 lo, hi;
  ASSERT_TRUE(mesh_bounds(*scene.objects.at(0).mesh, lo, hi));
  // Centre (1, 0.5, 0.5); a quarter turn swaps the 2-wide x extent and the 1-wide z extent.
  expect_near3(lo, glm::vec3(10.5f, 0.0f, -0.5f), 1e-5f);
  expect_near3(hi, glm::vec3(11.5f, 1.0f, 1.5f), 1e-5f);
  EXPECT_EQ(scene.objects[0].mesh->triangles.size(), 12u);
}

TEST(SceneLoader, TeapotIsScaledThenPlacedOnItsBase) {
  const Scene scene = parse_scene(R"({
    "materials": {"m": {}},
    "objects": [{"type": "teapot", "position": [1, 2, 3], "scale": 0.5, "tessellation": 4,
                 "material": "m"}]})",
                                  "teapot.json");
  glm::vec3 lo, hi;
  ASSERT_TRUE(mesh_bounds(*scene.objects.at(0).mesh, lo, hi));
  // The data rests on y = 0 and its lid knob tops out at 3.15 (utah-teapot.txt).
  EXPECT_NEAR(lo.y, 2.0f, 1e-4f);
  EXPECT_NEAR(hi.y, 2.0f + 0.5f * 3.15f, 1e-3f);
  EXPECT_EQ(scene.objects[0].params.tessellation, 4);
}

TEST(SceneLoader, MeshPathResolvesAgainstTheSceneFolder) {
  ScratchFolder folder;
  std::filesystem::create_directories(folder.path() / "models");
  write_file(folder.file("models/parts.obj"), kTwoPartObj);
  write_file(folder.file("models/parts.mtl"), kTwoPartMtl);
  write_file(folder.file("scene.json"), R"({
    "materials": {"grey": {}},
    "objects": [{"type": "mesh", "file": "models/parts.obj", "position": [1, 0, 0], "scale": 2,
                 "smooth": false, "material": "grey"}]})");
  const Scene scene = load_scene(folder.file("scene.json"));
  ASSERT_EQ(scene.objects.size(), 1u);  // with a scene material every part is one object
  const Mesh& mesh = *scene.objects[0].mesh;
  EXPECT_EQ(mesh.triangles.size(), 2u);
  EXPECT_FALSE(mesh.smooth());
  glm::vec3 lo, hi;
  ASSERT_TRUE(mesh_bounds(mesh, lo, hi));
  expect_near3(lo, glm::vec3(1.0f, 0.0f, 0.0f), 1e-6f);  // 2 * [0, 1] + (1, 0, 0)
  expect_near3(hi, glm::vec3(3.0f, 2.0f, 2.0f), 1e-6f);
}

TEST(SceneLoader, MeshWithoutMaterialGetsOneObjectPerMtlMaterial) {
  ScratchFolder folder;
  write_file(folder.file("parts.obj"), kTwoPartObj);
  write_file(folder.file("parts.mtl"), kTwoPartMtl);
  write_file(folder.file("scene.json"), R"({
    "objects": [{"type": "mesh", "name": "thing", "file": "parts.obj"}]})");
  const Scene scene = load_scene(folder.file("scene.json"));
  ASSERT_EQ(scene.objects.size(), 2u);
  EXPECT_EQ(scene.objects[0].name, "thing/red");
  EXPECT_EQ(scene.objects[0].params.group, "red");
  EXPECT_EQ(scene.material_names[scene.objects[0].material], "parts/red");
  EXPECT_EQ(scene.objects[1].name, "thing/blue");
  const Material& blue = scene.materials[scene.objects[1].material];
  EXPECT_EQ(blue.diffuse, glm::vec3(0.0f, 0.0f, 0.7f));
  EXPECT_EQ(blue.shininess, 20.0f);
}

TEST(SceneLoader, MeshWithoutMaterialOrMtlGetsTheDefaultGrey) {
  ScratchFolder folder;
  write_file(folder.file("plain.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write_file(folder.file("scene.json"), R"({"objects": [{"type": "mesh", "file": "plain.obj"}]})");
  const Scene scene = load_scene(folder.file("scene.json"));
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.material_names.at(scene.objects[0].material), "default");
  EXPECT_EQ(scene.materials.at(scene.objects[0].material), Material{});
}

TEST(SceneLoader, DegenerateQuadIsAWarningNotAnError) {
  std::vector<std::string> warnings;
  const Scene scene = parse_scene(R"({
    "materials": {"m": {}},
    "objects": [{"type": "quad", "vertices": [[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]],
                 "material": "m"}]})",
                                  "flat.json", &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("objects[0]"), std::string::npos) << warnings[0];
  EXPECT_TRUE(scene.objects.at(0).mesh->triangles.empty());
}

TEST(SceneLoader, EveryShippedSceneRoundTripsThroughItsJsonText) {
  for (const char* name : kShippedScenes) {
    const Scene scene = load_scene(shipped_scene(name));
    const Scene again = parse_scene(scene_to_json_text(scene), scene.path);
    SCOPED_TRACE(name);
    expect_scenes_equal(scene, again);
  }
}

TEST(SceneLoader, SceneWithEveryKindOfObjectRoundTripsExactly) {
  ScratchFolder folder;
  write_file(folder.file("parts.obj"), kTwoPartObj);
  write_file(folder.file("parts.mtl"), kTwoPartMtl);
  write_file(folder.file("scene.json"), R"({
    "camera": {"eye": [0.1, 0.2, 7.3], "target": [0, 0.3, 0], "up": [0, 1, 0.1], "fov_y": 33.3},
    "background": [0.01, 0.02, 0.03], "ambient": [0.3, 0.2, 0.1],
    "lights": [{"position": [1, 5, 2], "ambient": [0.1, 0.1, 0.1], "diffuse": [0.9, 0.8, 0.7],
                "specular": [1, 1, 1], "attenuation": [1, 0.01, 0.001]}],
    "materials": {"a": {"preset": "ruby", "shininess": 12.345},
                  "b": {"ambient": [0.1, 0, 0], "diffuse": [0.6, 0.1, 0.1], "specular": [1, 1, 1],
                        "emission": [0.05, 0, 0], "shininess": 64}},
    "objects": [
      {"type": "sphere", "center": [0.1, 0.7, -0.3], "radius": 0.3333, "material": "a"},
      {"type": "quad", "vertices": [[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]], "material": "b"},
      {"type": "box", "min": [-0.1, 0, -0.2], "max": [0.3, 0.7, 0.1], "rotate_y": 17.5,
       "position": [0.2, 0, 0.1], "material": "b"},
      {"type": "teapot", "position": [0, 0, 1], "scale": [0.1, 0.2, 0.3], "rotate_y": -30,
       "tessellation": 3, "smooth": false, "material": "a"},
      {"type": "mesh", "file": "parts.obj", "scale": 0.7, "rotate_y": 45},
      {"type": "mesh", "name": "merged", "file": "parts.obj", "material": "a",
       "crease_angle": 62.5}
    ],
    "render": {"width": 321, "height": 123, "spp": 7, "model": "blinn-phong", "shadows": false,
               "energy_normalize": true, "srgb": true, "seed": 4000000000, "pow": "fast"}})");
  const Scene scene = load_scene(folder.file("scene.json"));
  ASSERT_EQ(scene.objects.size(), 7u);  // the first mesh splits into its two MTL materials
  EXPECT_EQ(scene.objects.at(6).params.crease_angle, 62.5f);
  EXPECT_EQ(scene.objects.at(5).params.crease_angle, kDefaultCreaseAngle);
  expect_scenes_equal(scene, parse_scene(scene_to_json_text(scene), scene.path));

  // Saved into another folder, the relative OBJ path is rebased and still finds the file.
  std::filesystem::create_directories(folder.path() / "copies");
  save_scene(scene, folder.file("copies/saved.json"));
  const Scene saved = load_scene(folder.file("copies/saved.json"));
  EXPECT_EQ(saved.objects.at(4).params.file, "../parts.obj");
  EXPECT_EQ(saved.objects.at(4).mesh->positions, scene.objects.at(4).mesh->positions);
  EXPECT_EQ(saved.materials, scene.materials);
}

TEST(SceneLoader, ValidateSceneRefusesAnOverrideThatBreaksTheRenderBlock) {
  Scene scene = load_scene(shipped_scene("spheres"));
  scene.render.spp = 0;
  try {
    validate_scene(scene);
    FAIL() << "spp 0 accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "render.spp");
    EXPECT_NE(std::string(error.what()).find("spheres.json"), std::string::npos);
  }
}

}  // namespace
}  // namespace gloss

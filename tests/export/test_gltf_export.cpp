// glTF export (export/gltf_export.h): the default scene with a light of each type and a
// diffuse map, written as .gltf and .glb, read back by gloss (exact constants through extras)
// and by assimp (meshes, camera, lights), with light intensities and cones worked by hand.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <assimp/Importer.hpp>
#include <nlohmann/json.hpp>

#include "base/error.h"
#include "base/image.h"
#include "export/gltf_export.h"
#include "io/image/image_io.h"
#include "io/model/model_loader.h"
#include "io/scene/material_maps.h"
#include "io/scene/scene_loader.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

constexpr double kPi = 3.14159265358979323846;

// spheres.json with a directional light, a spot and a checker diffuse map on the first material,
// the scene's path moved into the scratch folder (where the map is).
Scene test_scene(const ScratchFolder& folder) {
  Scene scene = load_scene(std::string(GLOSS_SCENES_DIR) + "/spheres.json");
  scene.path = folder.file("scene.json");
  Image checker(4, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) checker.at(x, y) = glm::vec3((x + y) % 2 ? 0.2f : 0.9f);
  write_png(folder.file("checker.png"), checker, true);
  TextureMap map;
  map.file = "checker.png";
  MapReadContext context;
  context.file = scene.path;
  context.base_dir = folder.path().string();
  read_map(map, MapSlot::diffuse, context);
  scene.materials[0].map(MapSlot::diffuse) = map;
  Light sun;
  sun.type = LightType::directional;
  sun.direction = {0.0f, -1.0f, -1.0f};
  sun.diffuse = {0.5f, 0.25f, 0.0f};
  Light spot;
  spot.type = LightType::spot;
  spot.position = {0.0f, 4.0f, 0.0f};
  spot.direction = {0.0f, -1.0f, 0.0f};
  spot.cutoff = 30.0f;
  spot.inner = 20.0f;
  spot.attenuation = {0.0f, 0.0f, 1.0f};
  scene.lights.push_back(sun);
  scene.lights.push_back(spot);
  return scene;
}

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

class GltfExport : public ::testing::Test {
 protected:
  void SetUp() override {
    scene = test_scene(folder);
    conversions = convert_materials(scene);
  }
  ScratchFolder folder;
  Scene scene;
  std::vector<MaterialConversion> conversions;
};

// gloss -> glTF -> gloss: every material's constants come back bit for bit through extras, in
// both containers, and the map with them.
TEST_F(GltfExport, GlossReadsItsOwnFileExactly) {
  for (const char* name : {"out.gltf", "out.glb"}) {
    SCOPED_TRACE(name);
    const std::string path = folder.file(name);
    const GltfExportResult result = export_gltf(scene, conversions, path);
    EXPECT_GT(result.bytes, 0u);
    const Model model = load_model(path);
    ASSERT_EQ(model.materials.size(), scene.materials.size());
    EXPECT_EQ(model.exact_materials, static_cast<int>(scene.materials.size()));
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
      SCOPED_TRACE(scene.material_names[i]);
      const Material& want = scene.materials[i];
      const auto at = std::find(model.material_names.begin(), model.material_names.end(),
                                scene.material_names[i]);
      ASSERT_NE(at, model.material_names.end());
      const Material& got = model.materials[at - model.material_names.begin()];
      EXPECT_EQ(got.ambient, want.ambient);
      EXPECT_EQ(got.diffuse, want.diffuse);
      EXPECT_EQ(got.specular, want.specular);
      EXPECT_EQ(got.emission, want.emission);
      EXPECT_EQ(got.shininess, want.shininess);
      // The map on the first material only.
      EXPECT_EQ(got.has_map(MapSlot::diffuse), i == 0);
    }
    // One part per object: three spheres, each with its own material.
    EXPECT_EQ(model.parts.size(), 3u);
  }
}

// assimp reads the file as any glTF reader would: a mesh per object, the camera, three lights
// of the right types with the spot's cone, nodes where the scene puts things.
TEST_F(GltfExport, AssimpReadsMeshesCameraAndLights) {
  const std::string path = folder.file("out.glb");
  export_gltf(scene, conversions, path);
  Assimp::Importer importer;
  const aiScene* s = importer.ReadFile(path, aiProcess_ValidateDataStructure);
  ASSERT_NE(s, nullptr) << importer.GetErrorString();
  EXPECT_EQ(s->mNumMeshes, scene.objects.size());
  ASSERT_EQ(s->mNumCameras, 1u);
  ASSERT_EQ(s->mNumLights, 3u);
  EXPECT_EQ(s->mLights[0]->mType, aiLightSource_POINT);
  EXPECT_EQ(s->mLights[1]->mType, aiLightSource_DIRECTIONAL);
  EXPECT_EQ(s->mLights[2]->mType, aiLightSource_SPOT);
  EXPECT_NEAR(s->mLights[2]->mAngleOuterCone, 30.0 * kPi / 180.0, 1e-6);
  EXPECT_NEAR(s->mLights[2]->mAngleInnerCone, 20.0 * kPi / 180.0, 1e-6);
  // The first sphere's node: translated to its centre, scaled by its radius.
  const aiNode* node = s->mRootNode->FindNode(scene.objects[0].name.c_str());
  ASSERT_NE(node, nullptr);
  const aiMatrix4x4& m = node->mTransformation;
  EXPECT_NEAR(m.a4, scene.objects[0].center.x, 1e-6);
  EXPECT_NEAR(m.b4, scene.objects[0].center.y, 1e-6);
  EXPECT_NEAR(m.c4, scene.objects[0].center.z, 1e-6);
  EXPECT_NEAR(m.a1, scene.objects[0].radius, 1e-6);
  // The camera's node at the eye, looking at the target: its -Z is the view direction.
  const aiNode* cam = s->mRootNode->FindNode("camera");
  ASSERT_NE(cam, nullptr);
  const aiMatrix4x4& c = cam->mTransformation;
  const glm::vec3 eye = scene.camera.eye, ahead = glm::normalize(scene.camera.target - eye);
  EXPECT_NEAR(c.a4, eye.x, 1e-5);
  EXPECT_NEAR(c.b4, eye.y, 1e-5);
  EXPECT_NEAR(c.c4, eye.z, 1e-5);
  EXPECT_NEAR(-c.a3, ahead.x, 1e-5);
  EXPECT_NEAR(-c.b3, ahead.y, 1e-5);
  EXPECT_NEAR(-c.c3, ahead.z, 1e-5);
}

// Photometric intensities by hand: a directional light of Ld peak 0.5 is pi 0.5 lux with colour
// Ld / 0.5; a point light (attenuation c0 = 1) matched at its distance d to the camera target
// is pi d^2 candela; a spot with 1 / d^2 (c2 = 1) is pi candela whatever d. The material keeps
// the fit and its exact constants.
TEST_F(GltfExport, LightIntensitiesAndMaterialByHand) {
  const std::string path = folder.file("out.gltf");
  export_gltf(scene, conversions, path);
  const nlohmann::json doc = read_json(path);
  const nlohmann::json& lights = doc["extensions"]["KHR_lights_punctual"]["lights"];
  ASSERT_EQ(lights.size(), 3u);
  const Light& point = scene.lights[0];
  ASSERT_EQ(point.attenuation, glm::vec3(1.0f, 0.0f, 0.0f));
  const double d = glm::length(glm::dvec3(scene.camera.target) - glm::dvec3(point.position));
  const double peak = std::max({point.diffuse.x, point.diffuse.y, point.diffuse.z});
  EXPECT_NEAR(lights[0]["intensity"].get<double>(), kPi * peak * d * d, 1e-9 * d * d);
  EXPECT_NEAR(lights[1]["intensity"].get<double>(), kPi * 0.5, 1e-9);
  EXPECT_EQ(lights[1]["color"], nlohmann::json::array({1.0, 0.5, 0.0}));
  EXPECT_NEAR(lights[2]["intensity"].get<double>(), kPi, 1e-9);
  const nlohmann::json& m = doc["materials"][1];
  EXPECT_EQ(m["name"], scene.material_names[1]);
  EXPECT_NEAR(m["pbrMetallicRoughness"]["roughnessFactor"].get<double>(),
              conversions[1].gltf.material.roughness, 1e-12);
  EXPECT_EQ(m["extras"]["gloss"]["shininess"].get<float>(), scene.materials[1].shininess);
  EXPECT_EQ(doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"], 0);
  EXPECT_EQ(doc["images"][0]["uri"], "checker.png");
  EXPECT_EQ(doc["buffers"][0]["uri"], "out.bin");
}

// A scaled, turned and moved diffuse map and a normal map: KHR_texture_transform worked by hand
// (scale (2, 3), 30 degrees, offset (0.25, -0.5) on meshes carrying (u, 1 - v): offset
// (0.25 - 3 sin 30, 1 + 0.5 - 3 cos 30) = (-1.25, -1.0980762)), declared in extensionsUsed, and
// gloss reading the file back (through assimp's transform) with the same map coordinates.
TEST_F(GltfExport, MapTransformsRoundTrip) {
  TextureMap& diffuse = scene.materials[0].map(MapSlot::diffuse);
  diffuse.scale = {2.0f, 3.0f};
  diffuse.rotation = 30.0f;
  diffuse.offset = {0.25f, -0.5f};
  diffuse.wrap = {Wrap::mirror, Wrap::clamp};
  TextureMap normal = diffuse;
  normal.scale = glm::vec2(1.0f);
  normal.rotation = 0.0f;
  normal.offset = glm::vec2(0.0f);
  normal.wrap = {Wrap::repeat, Wrap::repeat};
  scene.materials[0].map(MapSlot::normal) = normal;
  scene.materials[0].normal_scale = 0.5f;
  for (const char* name : {"maps.gltf", "maps.glb"}) {
    SCOPED_TRACE(name);
    const std::string path = folder.file(name);
    export_gltf(scene, conversions, path);
    if (std::string(name) == "maps.gltf") {
      const nlohmann::json doc = read_json(path);
      const nlohmann::json& used = doc["extensionsUsed"];
      EXPECT_NE(std::find(used.begin(), used.end(), "KHR_texture_transform"), used.end());
      const nlohmann::json& material = doc["materials"][0];
      const nlohmann::json& base = material["pbrMetallicRoughness"]["baseColorTexture"];
      const nlohmann::json& t = base["extensions"]["KHR_texture_transform"];
      EXPECT_NEAR(t["offset"][0].get<double>(), -1.25, 1e-6);
      EXPECT_NEAR(t["offset"][1].get<double>(), -1.0980762, 1e-6);
      EXPECT_NEAR(t["rotation"].get<double>(), kPi / 6.0, 1e-6);
      EXPECT_EQ(t["scale"], nlohmann::json::array({2.0, 3.0}));
      EXPECT_EQ(t["texCoord"], 0);
      const nlohmann::json& sampler = doc["samplers"][base["index"].get<int>()];
      EXPECT_EQ(sampler["wrapS"], 33648);  // MIRRORED_REPEAT
      EXPECT_EQ(sampler["wrapT"], 33071);  // CLAMP_TO_EDGE
      // The plain normal map has no transform, and its scale.
      EXPECT_FALSE(material["normalTexture"].contains("extensions"));
      EXPECT_EQ(material["normalTexture"]["scale"], 0.5);
    }
    const Model model = load_model(path);
    const auto at = std::find(model.material_names.begin(), model.material_names.end(),
                              scene.material_names[0]);
    ASSERT_NE(at, model.material_names.end());
    const Material& got = model.materials[at - model.material_names.begin()];
    ASSERT_TRUE(got.has_map(MapSlot::diffuse));
    const TextureMap& back = got.map(MapSlot::diffuse);
    EXPECT_NEAR(back.scale.x, 2.0f, 1e-5f);
    EXPECT_NEAR(back.scale.y, 3.0f, 1e-5f);
    EXPECT_NEAR(back.rotation, 30.0f, 1e-4f);
    EXPECT_NEAR(back.offset.x, 0.25f, 1e-5f);
    EXPECT_NEAR(back.offset.y, -0.5f, 1e-5f);
    EXPECT_EQ(back.wrap[0], Wrap::mirror);
    EXPECT_EQ(back.wrap[1], Wrap::clamp);
    ASSERT_TRUE(got.has_map(MapSlot::normal));
    EXPECT_TRUE(plain_settings(got.map(MapSlot::normal)));
    EXPECT_FLOAT_EQ(got.normal_scale, 0.5f);
  }
}

// A flat mesh (spheres.json's floor quad, no normals) under a normal-mapped material is written
// with face normals (its 2 triangles unwelded: 6 vertices) and tangents, so no viewer has to
// make its own tangent space. The normal follows the winding, as gloss's face normal: (8,0,-8) -
// (-8,0,-8) = (16,0,0) cross (8,0,6) - (-8,0,-8) = (16,0,14) is (0,-224,0), -Y (the material is
// double-sided); the tangent runs along x, as u does.
TEST_F(GltfExport, NormalMappedFlatMeshGetsNormalsAndTangents) {
  const auto floor = std::find(scene.material_names.begin(), scene.material_names.end(), "floor");
  ASSERT_NE(floor, scene.material_names.end());
  scene.materials[floor - scene.material_names.begin()].map(MapSlot::normal) =
      scene.materials[0].map(MapSlot::diffuse);
  const std::string path = folder.file("flat.gltf");
  export_gltf(scene, conversions, path);
  const nlohmann::json doc = read_json(path);
  const auto mesh = std::find_if(doc["meshes"].begin(), doc["meshes"].end(),
                                 [](const nlohmann::json& m) { return m["name"] == "floor"; });
  ASSERT_NE(mesh, doc["meshes"].end());
  const nlohmann::json& attributes = (*mesh)["primitives"][0]["attributes"];
  ASSERT_TRUE(attributes.contains("NORMAL") && attributes.contains("TANGENT")) << attributes;
  EXPECT_EQ(doc["accessors"][attributes["POSITION"].get<int>()]["count"], 6);
  Assimp::Importer importer;
  const aiScene* s = importer.ReadFile(path, aiProcess_ValidateDataStructure);
  ASSERT_NE(s, nullptr) << importer.GetErrorString();
  for (unsigned m = 0; m < s->mNumMeshes; ++m) {
    if (std::string(s->mMeshes[m]->mName.C_Str()) != "floor") continue;
    const aiMesh& quad = *s->mMeshes[m];
    ASSERT_TRUE(quad.HasNormals() && quad.HasTangentsAndBitangents());
    EXPECT_NEAR(quad.mNormals[0].y, -1.0f, 1e-6f);
    EXPECT_NEAR(std::abs(quad.mTangents[0].x), 1.0f, 1e-5f);
  }
}

// Another extension is refused, naming the file; a folder that does not exist leaves nothing.
TEST_F(GltfExport, BadPathsFailCleanly) {
  EXPECT_THROW(export_gltf(scene, conversions, folder.file("out.obj")), InputError);
  EXPECT_THROW(export_gltf(scene, conversions, folder.file("missing/out.gltf")), RuntimeFailure);
  EXPECT_FALSE(std::filesystem::exists(folder.file("missing")));
}

TEST_F(GltfExport, AFailedGltfLeavesItsOldBinBeside) {
  // out.gltf cannot be written (a folder holds its name): the export fails, and the out.bin of
  // an earlier export is still the one it was, not a new .bin beside the old .gltf.
  std::filesystem::create_directory(folder.file("out.gltf"));
  { std::ofstream(folder.file("out.bin"), std::ios::binary) << "old"; }
  EXPECT_THROW(export_gltf(scene, conversions, folder.file("out.gltf")), RuntimeFailure);
  std::ifstream in(folder.file("out.bin"), std::ios::binary);
  const std::string kept((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(kept, "old");
}

}  // namespace
}  // namespace gloss

// three.js export (export/threejs_export.h): spheres.json with a scaled, turned and moved
// diffuse map and a normal map on the first material, written into a folder below the scene's:
// the JSON Object format's images, textures and material links checked by hand against
// three.js's ObjectLoader/MaterialLoader fields, its uv transform (Matrix3.setUvTransform) worked
// against gloss's map coordinates, and the maps three.js cannot take as notices.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "base/image.h"
#include "export/material_conversion.h"
#include "export/threejs_export.h"
#include "io/image/image_io.h"
#include "io/scene/material_maps.h"
#include "io/scene/scene_loader.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

constexpr double kPi = 3.14159265358979323846;
using nlohmann::json;

class ThreejsExportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    scene = load_scene(std::string(GLOSS_SCENES_DIR) + "/spheres.json");
    scene.path = folder.file("scene.json");
    Image checker(4, 4);
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x) checker.at(x, y) = glm::vec3((x + y) % 2 ? 0.2f : 0.9f);
    write_png(folder.file("checker.png"), checker, true);
    Material& m = scene.materials[0];
    m.map(MapSlot::diffuse) = read("checker.png", MapSlot::diffuse);
    m.map(MapSlot::diffuse).scale = {2.0f, 2.0f};
    m.map(MapSlot::diffuse).rotation = 30.0f;
    m.map(MapSlot::diffuse).offset = {0.25f, -0.5f};
    m.map(MapSlot::diffuse).wrap = {Wrap::mirror, Wrap::clamp};
    m.map(MapSlot::normal) = read("checker.png", MapSlot::normal);
    m.normal_scale = 0.5f;
  }
  TextureMap read(const std::string& file, MapSlot slot) {
    TextureMap map;
    map.file = file;
    MapReadContext context;
    context.file = scene.path;
    context.base_dir = folder.path().string();
    read_map(map, slot, context);
    return map;
  }
  ThreejsExport run() {
    return threejs_export(scene, convert_materials(scene), folder.file("web/materials.json"));
  }
  ScratchFolder folder;
  Scene scene;
};

const json& by_uuid(const json& list, const json& uuid) {
  const auto at = std::find_if(list.begin(), list.end(),
                               [&](const json& entry) { return entry["uuid"] == uuid; });
  EXPECT_NE(at, list.end()) << uuid;
  return *at;
}

TEST_F(ThreejsExportTest, MaterialsLinkTexturesAndImages) {
  const ThreejsExport out = run();
  EXPECT_TRUE(out.notices.empty());
  const json doc = json::parse(out.json);
  EXPECT_EQ(doc["metadata"]["type"], "Object");
  // One image, named relative to the JSON's folder (web/), shared by both maps.
  ASSERT_EQ(doc["images"].size(), 1u);
  EXPECT_EQ(doc["images"][0]["url"], "../checker.png");
  ASSERT_EQ(doc["textures"].size(), 2u);

  const json& phong = by_uuid(doc["materials"], "gloss-phong-0");
  EXPECT_EQ(phong["type"], "MeshPhongMaterial");
  const json& map = by_uuid(doc["textures"], phong["map"]);
  EXPECT_EQ(map["image"], doc["images"][0]["uuid"]);
  EXPECT_EQ(map["repeat"], json::array({2.0, 2.0}));
  EXPECT_EQ(map["offset"], json::array({0.25, -0.5}));
  EXPECT_EQ(map["center"], json::array({0.0, 0.0}));
  EXPECT_NEAR(map["rotation"].get<double>(), -kPi / 6.0, 1e-12);  // three.js turns clockwise
  EXPECT_EQ(map["wrap"], json::array({1002, 1001}));  // MirroredRepeatWrapping, ClampToEdge
  EXPECT_EQ(map["flipY"], true);
  EXPECT_EQ(map["colorSpace"], "srgb");
  EXPECT_EQ(map["channel"], 0);

  const json& normal = by_uuid(doc["textures"], phong["normalMap"]);
  EXPECT_FALSE(normal.contains("colorSpace"));  // data, not colour
  EXPECT_EQ(normal["wrap"], json::array({1000, 1000}));
  EXPECT_EQ(phong["normalScale"], json::array({0.5, 0.5}));

  // The Standard material shares the textures; the other materials have none.
  const json& standard = by_uuid(doc["materials"], "gloss-standard-0");
  EXPECT_EQ(standard["map"], phong["map"]);
  EXPECT_EQ(standard["normalMap"], phong["normalMap"]);
  EXPECT_FALSE(by_uuid(doc["materials"], "gloss-phong-1").contains("map"));

  // ObjectLoader needs an object: a Scene with a sphere per material and kind, each naming a
  // material of the file and the one geometry.
  const json& children = doc["object"]["children"];
  ASSERT_EQ(children.size(), 2 * scene.materials.size());
  for (const json& child : children) {
    by_uuid(doc["materials"], child["material"]);
    EXPECT_EQ(child["geometry"], doc["geometries"][0]["uuid"]);
  }
}

// three.js's texture matrix with center (0, 0) (Matrix3.setUvTransform): u' = rx (c u + s v) +
// ox, v' = ry (-s u + c v) + oy, c = cos rotation, s = sin rotation. For (u, v) = (0.3, 0.7) it
// gives gloss's (u, v) * 2 turned 30 degrees counter-clockwise plus (0.25, -0.5):
// (0.6 cos 30 - 1.4 sin 30 + 0.25, 0.6 sin 30 + 1.4 cos 30 - 0.5) = (0.069615, 1.012436).
TEST_F(ThreejsExportTest, UvTransformMatchesGlossByHand) {
  const json doc = json::parse(run().json);
  const json& t = by_uuid(doc["textures"], by_uuid(doc["materials"], "gloss-phong-0")["map"]);
  const double r = t["rotation"], c = std::cos(r), s = std::sin(r);
  const double u = 0.3, v = 0.7;
  const double mu = t["repeat"][0].get<double>() * (c * u + s * v) + t["offset"][0].get<double>();
  const double mv = t["repeat"][1].get<double>() * (-s * u + c * v) + t["offset"][1].get<double>();
  EXPECT_NEAR(mu, 0.069615, 1e-6);
  EXPECT_NEAR(mv, 1.012436, 1e-6);
}

// What three.js cannot take is a note: a shininess map (no slot), a specular map on
// MeshStandardMaterial, a non-uniform scale with a rotation (three.js scales after turning), a
// map that is not PNG or JPEG.
TEST_F(ThreejsExportTest, MapsThreejsCannotTakeAreNotes) {
  Material& m = scene.materials[1];
  m.map(MapSlot::shininess) = read("checker.png", MapSlot::shininess);
  m.map(MapSlot::specular) = read("checker.png", MapSlot::specular);
  m.map(MapSlot::specular).scale = {1.0f, 2.0f};
  m.map(MapSlot::specular).rotation = 90.0f;
  m.map(MapSlot::emission).file = "glow.exr";  // named only: never read
  const ThreejsExport out = run();
  const auto has = [&](const std::string& part) {
    return std::any_of(out.notices.begin(), out.notices.end(),
                       [&](const std::string& n) { return n.find(part) != std::string::npos; });
  };
  const std::string name = "material '" + scene.material_names[1] + "': ";
  EXPECT_TRUE(has(name + "shininess map not carried to three.js"));
  EXPECT_TRUE(has(name + "specular map not carried to three.js's MeshStandardMaterial"));
  EXPECT_TRUE(has(name + "specular map in three.js is approximate"));
  EXPECT_TRUE(has(name + "emission map not carried to three.js: the image is not PNG or JPEG"));
  const json doc = json::parse(out.json);
  const json& phong = by_uuid(doc["materials"], "gloss-phong-1");
  EXPECT_TRUE(phong.contains("specularMap"));
  EXPECT_FALSE(phong.contains("emissiveMap"));
  EXPECT_FALSE(by_uuid(doc["materials"], "gloss-standard-1").contains("specularMap"));
}

// three.js's hex colours are sRGB-encoded bytes: 0 -> 0, 1 -> 255, linear 0.5 -> 188
// (1.055 0.5^(1/2.4) - 0.055 = 0.7354, times 255 = 187.5 -> 188), 0.0031308 -> 10.3 -> 10.
TEST(ThreejsExport, SrgbBytesByHand) {
  EXPECT_EQ(srgb_byte(0.0), 0);
  EXPECT_EQ(srgb_byte(1.0), 255);
  EXPECT_EQ(srgb_byte(2.0), 255);
  EXPECT_EQ(srgb_byte(0.5), 188);
  EXPECT_EQ(srgb_byte(0.0031308), 10);
}

}  // namespace
}  // namespace gloss

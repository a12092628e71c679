// Maps as read: a colour map decoded from sRGB before filtering; models' maps from Debian's assimp
// test models (assimp-testmodels): the spider's five map_Kd
// images named with Windows paths (`.\wal67ar_small.jpg`), BoxTextured's sampler wrap modes
// (MIRRORED_REPEAT on s, CLAMP_TO_EDGE on t), and TextureTransformTest's KHR_texture_transform
// turned into the map's scale, rotation and offset so that the lookup lands where the
// extension's own formula puts it (checked at points, with the extension's matrices written out
// here from its specification).
#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "io/image/image_io.h"
#include "io/image/texture_reader.h"
#include "io/model/model_loader.h"
#include "texture/texture_lookup.h"

namespace gloss {
namespace {

const char* const kModels = "/usr/share/assimp/models";

bool have(const std::string& path) {
  return std::filesystem::exists(path);
}

int material_named(const Model& model, const std::string& name) {
  for (std::size_t i = 0; i < model.material_names.size(); ++i) {
    if (model.material_names[i] == name) return static_cast<int>(i);
  }
  return -1;
}

TEST(ModelMaps, TheSpiderHasItsFiveDiffuseMaps) {
  const std::string path = std::string(kModels) + "/OBJ/spider.obj";
  if (!have(path)) GTEST_SKIP() << "assimp-testmodels not installed";
  const Model model = load_model(path);
  const std::pair<const char*, const char*> expected[] = {{"Skin", "wal67ar_small.jpg"},
                                                          {"Brusttex", "wal69ar_small.jpg"},
                                                          {"HLeibTex", "SpiderTex.jpg"},
                                                          {"BeinTex", "drkwood2.jpg"},
                                                          {"Augentex", "engineflare1.jpg"}};
  for (const auto& [name, file] : expected) {
    const int m = material_named(model, name);
    ASSERT_GE(m, 0) << name;
    const TextureMap& map = model.materials[static_cast<std::size_t>(m)].map(MapSlot::diffuse);
    EXPECT_TRUE(map.present()) << name;
    EXPECT_EQ(std::filesystem::path(map.file).filename().string(), file) << name;
    EXPECT_GT(map.texture->levels.at(0).width, 1) << name;
  }
  EXPECT_TRUE(model.unused.empty()) << model.unused.front();
  for (const ModelPart& part : model.parts) EXPECT_TRUE(part.mesh.textured()) << part.material_name;
}

TEST(ModelMaps, BoxTexturedKeepsItsSamplersWrapModes) {
  // (The .glb of the same name has a sampler without wrap modes: repeat.)
  const std::string path = std::string(kModels) + "/glTF2/BoxTextured-glTF/BoxTextured.gltf";
  if (!have(path)) GTEST_SKIP() << "assimp-testmodels not installed";
  const Model model = load_model(path);
  const int m = material_named(model, "Texture");
  ASSERT_GE(m, 0);
  const TextureMap& map = model.materials[static_cast<std::size_t>(m)].map(MapSlot::diffuse);
  ASSERT_TRUE(map.present());
  EXPECT_EQ(map.wrap[0], Wrap::mirror);  // wrapS 33648 MIRRORED_REPEAT
  EXPECT_EQ(map.wrap[1], Wrap::clamp);   // wrapT 33071 CLAMP_TO_EDGE
}

// KHR_texture_transform in glTF's own (u, v), v down from the image's top: uv' = T R S uv with
// R = [[cos, sin], [-sin, cos]] (the extension's GLSL mat3(cos, -sin, 0, sin, cos, 0, 0, 0, 1),
// column-major; three.js's setUvTransform turns the same way).
glm::dvec2 gltf_transform(glm::dvec2 uv, glm::dvec2 offset, double rotation, glm::dvec2 scale) {
  const glm::dvec2 s = uv * scale;
  const double c = std::cos(rotation), n = std::sin(rotation);
  return glm::dvec2(c * s.x + n * s.y, -n * s.x + c * s.y) + offset;
}

TEST(ModelMaps, TextureTransformsLandWhereTheExtensionPutsThem) {
  const std::string path =
      std::string(kModels) + "/glTF2/textureTransform/TextureTransformTest.gltf";
  if (!have(path)) GTEST_SKIP() << "assimp-testmodels not installed";
  const Model model = load_model(path);
  struct Case {
    const char* material;
    glm::dvec2 offset;
    double rotation;
    glm::dvec2 scale;
  };
  const Case cases[] = {
      {"Offset U", {0.5, 0.0}, 0.0, {1, 1}},  {"Offset V", {0.0, 0.5}, 0.0, {1, 1}},
      {"Offset UV", {0.5, 0.5}, 0.0, {1, 1}}, {"Rotation", {0, 0}, 0.39269908169872414, {1, 1}},
      {"Scale", {0, 0}, 0.0, {1.5, 1.5}},     {"All", {-0.2, -0.1}, 0.3, {1.5, 1.5}},
      {"Correct", {0, 0}, 0.0, {1, 1}}};
  for (const Case& c : cases) {
    const int m = material_named(model, c.material);
    ASSERT_GE(m, 0) << c.material;
    const TextureMap& map = model.materials[static_cast<std::size_t>(m)].map(MapSlot::diffuse);
    ASSERT_TRUE(map.present()) << c.material;
    // gloss's (u, v) has v up: v = 1 - v_gltf, and a lookup at gloss's v' reads glTF's 1 - v'.
    for (const glm::dvec2 g :
         {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(0.25, 0.75), glm::dvec2(0.6, 0.1)}) {
      const glm::dvec2 want = gltf_transform(g, c.offset, c.rotation, c.scale);
      const glm::dvec2 got = map_coordinates(map, glm::dvec2(g.x, 1.0 - g.y));
      EXPECT_NEAR(got.x, want.x, 1e-5) << c.material << " at " << g.x << ", " << g.y;
      EXPECT_NEAR(1.0 - got.y, want.y, 1e-5) << c.material << " at " << g.x << ", " << g.y;
    }
  }
}

// A 2 x 1 colour map of bytes 64 and 192 (written by the PNG writer as is): its midpoint, half
// way between the two texel centres, is the mean of the sRGB-decoded values,
// (srgb(64/255) + srgb(192/255)) / 2 = (0.051269 + 0.527115) / 2 = 0.289192, not the decoded
// mean byte, srgb(128/255) = 0.215861; decoding twice would give 0.122027. As data (linear) the
// midpoint is 128/255.
TEST(ModelMaps, AColourMapsMidpointIsTheMeanOfItsDecodedTexels) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("gloss-srgb-2x1-" + std::to_string(::getpid()) + ".png");
  Image image(2, 1);
  image.at(0, 0) = glm::vec3(64.0f / 255.0f);
  image.at(1, 0) = glm::vec3(192.0f / 255.0f);
  write_png(path.string(), image);
  const auto colour = read_texture(path.string(), ImageData::colour);
  const auto data = read_texture(path.string(), ImageData::linear);
  std::filesystem::remove(path);
  const glm::dvec4 mid = bilinear(*colour, 0, 0.5, 0.5, Wrap::clamp, Wrap::clamp);
  EXPECT_NEAR(mid.x, 0.289192, 2e-6);
  EXPECT_NEAR(mid.y, 0.289192, 2e-6);
  const glm::dvec4 centre = bilinear(*colour, 0, 0.25, 0.5, Wrap::clamp, Wrap::clamp);
  EXPECT_NEAR(centre.x, 0.051269, 2e-6);  // texel 0's centre: its own decoded value
  EXPECT_NEAR(bilinear(*data, 0, 0.5, 0.5, Wrap::clamp, Wrap::clamp).x, 128.0 / 255.0, 2e-6);
}

TEST(ModelMaps, AMissingMapIsAWarningAndTheModelLoadsUntextured) {
  // BoxTextured's .gltf without its PNG beside it.
  const std::string from = std::string(kModels) + "/glTF2/BoxTextured-glTF";
  if (!have(from)) GTEST_SKIP() << "assimp-testmodels not installed";
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("gloss-model-maps-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(from + "/BoxTextured.gltf", dir / "BoxTextured.gltf",
                             std::filesystem::copy_options::overwrite_existing);
  std::filesystem::copy_file(from + "/BoxTextured0.bin", dir / "BoxTextured0.bin",
                             std::filesystem::copy_options::overwrite_existing);
  const Model model = load_model((dir / "BoxTextured.gltf").string());
  std::filesystem::remove_all(dir);
  const int m = material_named(model, "Texture");
  ASSERT_GE(m, 0);
  EXPECT_FALSE(model.materials[static_cast<std::size_t>(m)].has_map(MapSlot::diffuse));
  ASSERT_FALSE(model.unused.empty());
  EXPECT_NE(model.unused.front().find("CesiumLogoFlat.png"), std::string::npos)
      << model.unused.front();
}

}  // namespace
}  // namespace gloss

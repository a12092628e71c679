// A scene's materials that name several maps of one model (MODEL#MATERIAL/SLOT) load that model
// once per scene load, not once per map, and take the same textures a load of the model itself
// gives. The model: assimp-testmodels' ClearCoatTest.gltf, whose RoughVariations_Coating has a
// metallic-roughness texture (gloss makes its specular and shininess maps from it per texel),
// Partial_Coating a base colour image and BaseNorm_Base and SharedNorm_Coated normal images.
#include "io/model/model_map_cache.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "base/error.h"
#include "io/scene/material_maps.h"
#include "io/scene/scene_loader.h"

namespace gloss {
namespace {

const std::string kDir = "/usr/share/assimp/models/glTF2/ClearCoat-glTF";
const std::string kModel = kDir + "/ClearCoatTest.gltf";

struct Named {
  const char* material;
  MapSlot slot;
};
const Named kNamed[] = {{"RoughVariations_Coating", MapSlot::specular},
                        {"RoughVariations_Coating", MapSlot::shininess},
                        {"Partial_Coating", MapSlot::diffuse},
                        {"BaseNorm_Base", MapSlot::normal},
                        {"SharedNorm_Coated", MapSlot::normal}};

// Level 0 of each named map, from a load of the model itself.
std::vector<MipLevel> expected_levels(std::uint64_t* map_bytes = nullptr) {
  const Model model = load_model(kModel);
  if (map_bytes != nullptr) *map_bytes = model.map_bytes;
  std::vector<MipLevel> out;
  for (const Named& n : kNamed) {
    for (std::size_t m = 0; m < model.materials.size(); ++m) {
      if (model.material_names[m] != n.material) continue;
      const TextureMap& map = model.materials[m].map(n.slot);
      if (map.present()) out.push_back(map.texture->levels.at(0));
    }
  }
  return out;
}

void expect_same(const MipLevel& a, const MipLevel& b, const std::string& what) {
  EXPECT_EQ(a.width, b.width) << what;
  EXPECT_EQ(a.height, b.height) << what;
  EXPECT_TRUE(a.texels == b.texels) << what;
}

TEST(ModelMapCache, SeveralMapsOfOneModelLoadItOnce) {
  if (!std::filesystem::exists(kModel)) GTEST_SKIP() << "assimp-testmodels not installed";
  std::uint64_t model_map_bytes = 0;
  // Taken (and freed) first, so that the textures the model reads from files are not in memory
  // when the scene's references read them (they would then not be counted again).
  const std::vector<MipLevel> expected = expected_levels(&model_map_bytes);
  ASSERT_EQ(expected.size(), std::size(kNamed));

  // Two materials, the second naming the model by another spelling of its path.
  Material first, second;
  for (std::size_t i = 0; i < 3; ++i) {
    first.map(kNamed[i].slot).file =
        "ClearCoatTest.gltf#" + std::string(kNamed[i].material) + "/" + to_string(kNamed[i].slot);
  }
  second.map(MapSlot::normal).file = "./ClearCoatTest.gltf#BaseNorm_Base/normal";
  second.map(MapSlot::diffuse).file = "ClearCoatTest.gltf#Partial_Coating/diffuse";
  Material third;
  third.map(MapSlot::normal).file = "../ClearCoat-glTF/ClearCoatTest.gltf#SharedNorm_Coated/normal";

  ModelMapCache cache;
  std::uint64_t claimed = 0;
  MapReadContext context;
  context.file = "scene.json";
  context.base_dir = kDir;
  context.claimed_bytes = &claimed;
  context.model_maps = &cache;
  read_material_maps(first, "materials.first", context);
  read_material_maps(second, "materials.second", context);
  read_material_maps(third, "materials.third", context);
  EXPECT_EQ(cache.loads, 1);  // six references, one model

  for (std::size_t i = 0; i < 3; ++i) {
    ASSERT_TRUE(first.has_map(kNamed[i].slot)) << i;
    expect_same(first.map(kNamed[i].slot).texture->levels.at(0), expected[i], kNamed[i].material);
  }
  expect_same(second.map(MapSlot::normal).texture->levels.at(0), expected[3], "BaseNorm_Base");
  expect_same(third.map(MapSlot::normal).texture->levels.at(0), expected[4], "SharedNorm_Coated");
  // One texture for one map of the model, whichever material names it.
  EXPECT_EQ(second.map(MapSlot::diffuse).texture, first.map(MapSlot::diffuse).texture);
  // What the model's load decoded is claimed once: every map it read, not only those taken, and
  // not once per reference.
  EXPECT_EQ(claimed, model_map_bytes);
  std::uint64_t taken = 0;
  for (int s = 0; s < kMapSlots; ++s) {
    if (first.has_map(static_cast<MapSlot>(s)))
      taken += first.map(static_cast<MapSlot>(s)).texture->bytes();
  }
  EXPECT_GT(claimed, taken);
}

TEST(ModelMapCache, AMissingMaterialOrMapNamesTheModel) {
  if (!std::filesystem::exists(kModel)) GTEST_SKIP() << "assimp-testmodels not installed";
  ModelMapCache cache;
  MapReadContext context;
  context.base_dir = kDir;
  context.model_maps = &cache;
  TextureMap no_material;
  no_material.file = "ClearCoatTest.gltf#Nobody/diffuse";
  TextureMap no_map;
  no_map.file = "ClearCoatTest.gltf#Simple_Base/normal";
  try {
    read_map(no_material, MapSlot::diffuse, context);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), kDir + "/ClearCoatTest.gltf: has no material 'Nobody'");
  }
  try {
    read_map(no_map, MapSlot::normal, context);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              kDir +
                  "/ClearCoatTest.gltf: material 'Simple_Base' has no normal map (or its image "
                  "cannot be read)");
  }
  EXPECT_EQ(cache.loads, 1);
}

// Through a scene file: a model placed as an object and its maps named by the scene's own
// materials (as a saved scene names a model's maps) take the textures the model's load gives.
TEST(ModelMapCache, AScenesMaterialsTakeTheModelsMaps) {
  if (!std::filesystem::exists(kModel)) GTEST_SKIP() << "assimp-testmodels not installed";
  const std::vector<MipLevel> expected = expected_levels();
  ASSERT_EQ(expected.size(), std::size(kNamed));
  const std::string scene_text = R"({
    "objects": [{"type": "mesh", "file": ")" +
                                 kModel + R"(", "material": "coat"}],
    "materials": {"coat": {
      "specular_map": ")" + kModel +
                                 R"(#RoughVariations_Coating/specular",
      "shininess_map": ")" + kModel +
                                 R"(#RoughVariations_Coating/shininess",
      "diffuse_map": ")" + kModel +
                                 R"(#Partial_Coating/diffuse",
      "normal_map": ")" + kModel +
                                 R"(#BaseNorm_Base/normal"}}
  })";
  const Scene scene = parse_scene(scene_text, "/tmp/scene.json");
  const auto named = std::find(scene.material_names.begin(), scene.material_names.end(), "coat");
  ASSERT_NE(named, scene.material_names.end());
  const Material& coat =
      scene.materials[static_cast<std::size_t>(named - scene.material_names.begin())];
  for (std::size_t i = 0; i < 4; ++i) {
    ASSERT_TRUE(coat.has_map(kNamed[i].slot)) << i;
    expect_same(coat.map(kNamed[i].slot).texture->levels.at(0), expected[i], kNamed[i].material);
  }
}

}  // namespace
}  // namespace gloss

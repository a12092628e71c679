// The files a scene names, moved with it (io/scene/scene_files.h): Save As into another folder,
// a scene carried by a PNG. The expected names are worked out by hand from the folders.
#include "io/scene/scene_files.h"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "io/image/image_io.h"
#include "io/image/scene_in_png.h"
#include "io/scene/scene_loader.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

// A scene at /data/scenes/room.json naming one file of every kind.
Scene scene_naming_files() {
  Scene scene;
  scene.path = "/data/scenes/room.json";
  Object cup, pot;
  cup.type = pot.type = ObjectType::mesh;
  cup.params.file = "../models/cup.obj";
  pot.params.file = "/abs/pot.obj";
  scene.objects = {cup, pot};
  Material material;
  material.map(MapSlot::diffuse).file = "maps/wood.png";
  material.map(MapSlot::normal).file = "../models/cup.gltf#Glaze/normal";  // a model's own map
  material.map(MapSlot::bump).file = "/abs/bump.png";
  scene.materials = {material};
  scene.material_names = {"m"};
  scene.environment.file = "../environments/studio.exr";
  return scene;
}

TEST(SceneFiles, SaveAsRenamesEveryRelativeFileForTheNewFolder) {
  Scene scene = scene_naming_files();
  rebase_scene_files(scene, "/data/out/deep/copy.json");
  EXPECT_EQ(scene.path, "/data/out/deep/copy.json");
  EXPECT_EQ(scene.objects[0].params.file, "../../models/cup.obj");
  EXPECT_EQ(scene.objects[1].params.file, "/abs/pot.obj");
  const Material& m = scene.materials[0];
  EXPECT_EQ(m.map(MapSlot::diffuse).file, "../../scenes/maps/wood.png");
  EXPECT_EQ(m.map(MapSlot::normal).file, "../../models/cup.gltf#Glaze/normal");
  EXPECT_EQ(m.map(MapSlot::bump).file, "/abs/bump.png");
  EXPECT_EQ(scene.environment.file, "../../environments/studio.exr");

  rebase_scene_files(scene, "/data/room2.json");  // and back up, one folder above the first
  EXPECT_EQ(scene.objects[0].params.file, "models/cup.obj");
  EXPECT_EQ(scene.materials[0].map(MapSlot::diffuse).file, "scenes/maps/wood.png");
  EXPECT_EQ(scene.environment.file, "environments/studio.exr");
}

TEST(SceneFiles, AScenesFilesMadeAbsoluteAgainstItsFolder) {
  Scene scene = scene_naming_files();
  make_scene_files_absolute(scene, "/data/scenes");
  EXPECT_EQ(scene.objects[0].params.file, "/data/models/cup.obj");
  EXPECT_EQ(scene.objects[1].params.file, "/abs/pot.obj");
  EXPECT_EQ(scene.materials[0].map(MapSlot::diffuse).file, "/data/scenes/maps/wood.png");
  EXPECT_EQ(scene.materials[0].map(MapSlot::normal).file, "/data/models/cup.gltf#Glaze/normal");
  EXPECT_EQ(scene.environment.file, "/data/environments/studio.exr");
}

// An untitled scene's relative names are relative to the current folder (as the loader reads
// them): saved, they are named from the new file's folder.
TEST(SceneFiles, AnUntitledScenesNamesAreRelativeToTheCurrentFolder) {
  Scene scene = scene_naming_files();
  scene.path.clear();
  const std::filesystem::path here = std::filesystem::current_path();
  rebase_scene_files(scene, (here / "saved" / "room.json").string());
  EXPECT_EQ(scene.objects[0].params.file, "../../models/cup.obj");  // was ../models/cup.obj
  scene = scene_naming_files();
  scene.path.clear();
  make_scene_files_absolute(scene, "");
  EXPECT_EQ(scene.environment.file,
            (here.parent_path() / "environments" / "studio.exr").lexically_normal().string());
}

TEST(SceneFiles, AFileIsNamedRelativeToTheScenesFolder) {
  EXPECT_EQ(name_for_scene("/data/models/cup.obj", "/data/scenes/room.json"), "../models/cup.obj");
  EXPECT_EQ(name_for_scene("/data/scenes/maps/../maps/wood.png", "/data/scenes/room.json"),
            "maps/wood.png");
  // Untitled: relative to the current folder, as the loader reads an untitled scene's names.
  const std::filesystem::path here = std::filesystem::current_path();
  EXPECT_EQ(name_for_scene((here / "models" / "cup.obj").string(), ""), "models/cup.obj");
  EXPECT_EQ(name_for_scene("models/cup.obj", (here / "scenes" / "room.json").string()),
            "../models/cup.obj");
}

TEST(SceneFiles, MovingTheSceneLeavesTheSharedMapsOfItsCopiesAlone) {
  const Scene original = scene_naming_files();
  Scene moved = original;  // shares the maps (material.h)
  rebase_scene_files(moved, "/data/other/room.json");
  EXPECT_EQ(original.materials[0].map(MapSlot::diffuse).file, "maps/wood.png");
  EXPECT_EQ(moved.materials[0].map(MapSlot::diffuse).file, "../scenes/maps/wood.png");
  Scene same = original;
  rebase_scene_files(same, "/data/scenes/renamed.json");  // same folder: nothing to rename
  EXPECT_EQ(same.materials[0].map_storage, original.materials[0].map_storage);
}

// The shipped environment scene names "../environments/studio.exr": saved elsewhere (the editor's
// Save As kept that name; save_scene itself rebased it) and carried by a PNG written elsewhere
// (the PNG kept it relative), it opens again.
TEST(SceneFiles, TheShippedEnvironmentSceneSavedElsewhereOpensAgain) {
  const Scene scene = load_scene(std::string(GLOSS_ASSETS_DIR) + "/scenes/studio-metals.json");
  ScratchFolder folder;
  std::filesystem::create_directories(folder.path() / "a" / "b");
  const std::string copy = folder.file("a/b/copy.json");
  save_scene(scene, copy);
  Scene back;
  ASSERT_NO_THROW(back = load_scene(copy));
  EXPECT_TRUE(back.environment.present());
  EXPECT_EQ(std::filesystem::weakly_canonical(std::filesystem::path(folder.path() / "a" / "b") /
                                              back.environment.file),
            std::filesystem::weakly_canonical(std::string(GLOSS_ASSETS_DIR) +
                                              "/environments/studio.exr"));

  // A PNG of it, written anywhere, opens as the scene too.
  Image image(2, 1);
  write_png(folder.file("shot.png"), image, false,
            {{kSceneChunkKeyword, embedded_scene_text(scene)}});
  Scene from_png;
  ASSERT_NO_THROW(from_png = load_scene(folder.file("shot.png")));
  EXPECT_TRUE(from_png.environment.present());
  EXPECT_TRUE(std::filesystem::path(from_png.environment.file).is_absolute());
}

}  // namespace
}  // namespace gloss

// Crash recovery: the autosave writes the document after edits settle, the recovery file reads
// back to the same document, a clean document needs no file, and damaged files are errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "base/error.h"
#include "editor/model/document/command_layer.h"
#include "editor/model/session/autosave.h"
#include "io/scene/scene_loader.h"
#include "support/field_commands.h"
#include "support/test_scene.h"

namespace gloss {
namespace {

std::filesystem::path temp_folder(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("gloss-app-test-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(Autosave, RoundTripGivesBackTheEditedDocument) {
  const std::filesystem::path file = temp_folder("roundtrip") / "recovery.json";
  CommandLayer layer(test::two_sphere_scene());
  Autosaver autosaver(file, layer.revision(), 1.0, 10.0);
  layer.execute(ApplyPreset{1, "gold"});
  layer.execute(test::set_light(0, "position", {1.5f, 2.5f, 3.5f}));
  EXPECT_FALSE(autosaver.step(layer, 1, 0.0));  // the change is seen at t = 0 s
  EXPECT_FALSE(autosaver.step(layer, 1, 0.5));  // not quiet for 1 s yet
  EXPECT_TRUE(autosaver.step(layer, 1, 1.25));
  ASSERT_TRUE(std::filesystem::exists(file));

  const std::optional<Recovery> recovery = read_recovery(file);
  ASSERT_TRUE(recovery.has_value());
  EXPECT_EQ(recovery->selected_object, 1);
  EXPECT_FALSE(recovery->saved_at.empty());
  EXPECT_EQ(scene_to_json_text(recovery->scene), scene_to_json_text(layer.scene()));
  EXPECT_EQ(recovery->scene.lights[0].position, glm::vec3(1.5f, 2.5f, 3.5f));
  // Materials are found through their objects: the JSON form keeps names, not indices.
  const Scene& back = recovery->scene;
  EXPECT_NEAR(back.materials[back.objects[1].material].diffuse.x, 0.75164f, 1e-6f);  // gold
  EXPECT_EQ(back.materials[back.objects[1].material].preset, "gold");  // Reset to preset works
}

TEST(Autosave, ContinuousEditingStillSavesAfterTheLongestDelay) {
  const std::filesystem::path file = temp_folder("overdue") / "recovery.json";
  CommandLayer layer(test::two_sphere_scene());
  Autosaver autosaver(file, layer.revision(), 1.0, 10.0);
  bool written = false;
  for (int i = 0; i <= 110; ++i) {  // an edit every 0.1 s, never quiet for 1 s
    layer.execute(test::set_shininess(0, 10.0f + static_cast<float>(i)));
    written |= autosaver.step(layer, 0, 0.1 * i);
  }
  EXPECT_TRUE(written);
}

TEST(Autosave, NoEditsNoFileAndUndoToSavedRemovesIt) {
  const std::filesystem::path file = temp_folder("clean") / "recovery.json";
  CommandLayer layer(test::two_sphere_scene());
  Autosaver autosaver(file, layer.revision(), 1.0, 10.0);
  EXPECT_FALSE(autosaver.step(layer, 0, 5.0));
  EXPECT_FALSE(std::filesystem::exists(file));
  layer.execute(test::set_render("shadows", false));
  autosaver.step(layer, 0, 6.0);
  EXPECT_TRUE(autosaver.step(layer, 0, 7.5));
  EXPECT_TRUE(std::filesystem::exists(file));
  layer.undo();  // back to the state of the file on disk
  autosaver.step(layer, 0, 8.0);
  autosaver.step(layer, 0, 9.5);
  EXPECT_FALSE(std::filesystem::exists(file));
}

TEST(Autosave, DiscardRemovesTheFile) {
  const std::filesystem::path file = temp_folder("discard") / "recovery.json";
  CommandLayer layer(test::two_sphere_scene());
  Autosaver autosaver(file, layer.revision(), 0.0, 10.0);
  layer.execute(test::set_render("shadows", false));
  EXPECT_TRUE(autosaver.step(layer, 0, 1.0));
  autosaver.discard();
  EXPECT_FALSE(std::filesystem::exists(file));
  EXPECT_FALSE(read_recovery(file).has_value());
}

TEST(Autosave, DamagedFilesAreInputErrors) {
  const std::filesystem::path dir = temp_folder("damaged");
  std::ofstream(dir / "garbage.json") << "{ not json";
  std::ofstream(dir / "other.json") << R"({"materials": {}})";
  EXPECT_THROW(read_recovery(dir / "garbage.json"), InputError);
  EXPECT_THROW(read_recovery(dir / "other.json"), InputError);
}

TEST(Autosave, TheFileIsWrittenAtomically) {
  const std::filesystem::path dir = temp_folder("atomic");
  CommandLayer layer(test::two_sphere_scene());
  Autosaver autosaver(dir / "recovery.json", layer.revision(), 0.0, 10.0);
  layer.execute(test::set_render("shadows", false));
  ASSERT_TRUE(autosaver.step(layer, 0, 1.0));
  // Only the finished file is left: no temporary beside it.
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    (void)entry;
    ++files;
  }
  EXPECT_EQ(files, 1u);
}

// A write that fails (here the state folder is a file) is reported on screen at once, not
// thrown away: failure() and the notice say why, and the write is tried again until it works.
TEST(Autosave, AFailingWriteSetsTheNoticeAndIsRetried) {
  const std::filesystem::path dir = temp_folder("failing");
  std::ofstream(dir / "state") << "a file where the folder should be";
  const std::filesystem::path file = dir / "state" / "recovery.json";
  CommandLayer layer(test::two_sphere_scene());
  Autosaver autosaver(file, layer.revision(), 1.0, 10.0);
  layer.execute(ApplyPreset{1, "gold"});
  EXPECT_TRUE(autosave_notice(autosaver).empty());
  EXPECT_FALSE(autosaver.step(layer, 1, 0.0));
  bool written = true;
  EXPECT_NO_THROW(written = autosaver.step(layer, 1, 1.25));
  EXPECT_FALSE(written);
  EXPECT_EQ(autosaver.failure_count(), 1);
  EXPECT_EQ(autosaver.failure().rfind("cannot write " + file.string() + ": ", 0), 0u)
      << autosaver.failure();
  EXPECT_EQ(autosave_notice(autosaver).rfind("AUTOSAVE FAILING", 0), 0u);

  EXPECT_FALSE(autosaver.step(layer, 1, 2.0));  // not again every frame
  EXPECT_EQ(autosaver.failure_count(), 1);
  std::filesystem::remove(dir / "state");
  std::filesystem::create_directory(dir / "state");
  EXPECT_TRUE(autosaver.step(layer, 1, 6.25));  // 5 s after the failure
  EXPECT_TRUE(autosaver.failure().empty());
  EXPECT_TRUE(autosave_notice(autosaver).empty());
  EXPECT_TRUE(std::filesystem::exists(file));
}

// Names that are not UTF-8 (an MTL's "Terrain\xE6k") no longer make every autosave fail.
TEST(Autosave, NamesThatAreNotUtf8AreAutosaved) {
  const std::filesystem::path file = temp_folder("bytes") / "recovery.json";
  Scene scene = test::two_sphere_scene();
  scene.objects[0].name = "Terrain\xE6k";
  scene.material_names[0] = "t/Terrain\xE6k";
  CommandLayer layer(scene);
  Autosaver autosaver(file, layer.revision(), 1.0, 10.0);
  layer.execute(ApplyPreset{1, "gold"});
  EXPECT_FALSE(autosaver.step(layer, 1, 0.0));
  EXPECT_TRUE(autosaver.step(layer, 1, 1.25)) << autosaver.failure();
  const std::optional<Recovery> recovery = read_recovery(file);
  ASSERT_TRUE(recovery.has_value());
  EXPECT_EQ(recovery->scene.objects[0].name, "Terrain\xE6k");
}

}  // namespace
}  // namespace gloss

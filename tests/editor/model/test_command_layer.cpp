// The command layer's bookkeeping: gestures merge into one step, failed and no-op commands record
// nothing, the saved state is tracked through undo and redo, revisions never repeat.
#include <memory>

#include <gtest/gtest.h>

#include "editor/model/document/command_layer.h"
#include "support/field_commands.h"
#include "support/test_scene.h"

namespace gloss {
namespace {

TEST(CommandLayer, ADragIsOneUndoStepUntilSealed) {
  CommandLayer layer(test::two_sphere_scene());
  for (float s : {70.0f, 80.0f, 90.0f}) layer.execute(test::set_shininess(0, s));
  EXPECT_EQ(layer.undo_count(), 1u);
  layer.seal();
  layer.execute(test::set_shininess(0, 100.0f));
  EXPECT_EQ(layer.undo_count(), 2u);
  layer.undo();
  EXPECT_EQ(layer.scene().materials[0].shininess, 90.0f);
  layer.undo();
  EXPECT_EQ(layer.scene().materials[0].shininess, 64.0f);  // the value before the first drag
}

TEST(CommandLayer, DifferentKeysDoNotMerge) {
  CommandLayer layer(test::two_sphere_scene());
  layer.execute(test::set_shininess(0, 70.0f));
  layer.execute(test::set_shininess(1, 70.0f));
  layer.execute(test::set_material(0, "diffuse", glm::vec3(0.5f)));
  EXPECT_EQ(layer.undo_count(), 3u);
}

TEST(CommandLayer, UnkeyedCommandsAreAlwaysTheirOwnStep) {
  CommandLayer layer(test::two_sphere_scene());
  layer.execute(test::set_render("shadows", false));
  layer.execute(test::set_render("shadows", true));
  EXPECT_EQ(layer.undo_count(), 2u);
}

TEST(CommandLayer, AFailingCommandChangesNothing) {
  CommandLayer layer(test::two_sphere_scene());
  const std::uint64_t revision = layer.revision();
  EXPECT_THROW(layer.execute(test::set_shininess(5, 1.0f)), CommandError);
  EXPECT_THROW(layer.execute(test::set_shininess(0, -1.0f)), CommandError);
  EXPECT_THROW(layer.execute(ApplyPreset{0, "golld"}), CommandError);
  EXPECT_THROW(layer.execute(test::set_light(0, "attenuation", glm::vec3(0.0f))), CommandError);
  EXPECT_THROW(layer.execute(test::set_material(0, "diffuse", glm::vec3(-0.1f))), CommandError);
  EXPECT_THROW(layer.execute(RemoveLight{2}), CommandError);
  EXPECT_THROW(layer.execute(test::set_render("spp", 0)), CommandError);
  EXPECT_EQ(layer.revision(), revision);
  EXPECT_EQ(layer.undo_count(), 0u);
  EXPECT_TRUE(same_scene(layer.scene(), test::two_sphere_scene()));
}

// A value is checked by its field's rule before the setter converts it to the member's type:
// 1e300 for a float field (shininess) or an int field (spp) would be undefined behaviour there
// (the script's `render height 6811e395`, found by fuzz/fuzz_script, is in test_script.cpp).
TEST(CommandLayer, AValueBeyondTheMembersTypeIsRefusedBeforeConversion) {
  CommandLayer layer(test::two_sphere_scene());
  try {
    layer.execute(test::set_shininess(0, 1e300));
    ADD_FAILURE() << "shininess 1e300 was accepted";
  } catch (const CommandError& e) {
    EXPECT_NE(std::string(e.what()).find("must be a finite number"), std::string::npos) << e.what();
  }
  try {
    layer.execute(test::set_render("spp", 1e300));
    ADD_FAILURE() << "spp 1e300 was accepted";
  } catch (const CommandError& e) {
    EXPECT_NE(std::string(e.what()).find("render spp: must be a whole number"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(layer.scene().materials[0].shininess, 64.0f);
  EXPECT_EQ(layer.undo_count(), 0u);
}

TEST(CommandLayer, UnknownPresetNamesTheNearestOne) {
  CommandLayer layer(test::two_sphere_scene());
  try {
    layer.execute(ApplyPreset{0, "golld"});
    FAIL() << "no error";
  } catch (const CommandError& e) {
    EXPECT_NE(std::string(e.what()).find("'gold'"), std::string::npos) << e.what();
  }
}

TEST(CommandLayer, ANoOpRecordsNothing) {
  CommandLayer layer(test::two_sphere_scene());
  EXPECT_FALSE(layer.execute(test::set_shininess(0, 64.0f)));
  EXPECT_FALSE(layer.execute(test::set_render("shadows", true)));
  EXPECT_EQ(layer.undo_count(), 0u);
  EXPECT_FALSE(layer.dirty());
}

TEST(CommandLayer, DirtyFollowsTheSavedState) {
  CommandLayer layer(test::two_sphere_scene());
  EXPECT_FALSE(layer.dirty());
  layer.execute(test::set_render("shadows", false));
  EXPECT_TRUE(layer.dirty());
  layer.mark_saved();
  EXPECT_FALSE(layer.dirty());
  layer.undo();
  EXPECT_TRUE(layer.dirty());
  layer.redo();
  EXPECT_FALSE(layer.dirty());
  layer.reset(test::two_sphere_scene(), false);
  EXPECT_TRUE(layer.dirty());
  layer.reset(test::two_sphere_scene(), true);
  EXPECT_FALSE(layer.dirty());
}

TEST(CommandLayer, ANewEditClearsRedo) {
  CommandLayer layer(test::two_sphere_scene());
  layer.execute(test::set_render("shadows", false));
  layer.undo();
  EXPECT_TRUE(layer.can_redo());
  layer.execute(test::set_render("energy_normalize", true));
  EXPECT_FALSE(layer.can_redo());
  EXPECT_FALSE(layer.redo());
}

TEST(CommandLayer, RevisionsNeverRepeat) {
  CommandLayer layer(test::two_sphere_scene());
  std::vector<std::uint64_t> seen{layer.revision()};
  layer.execute(test::set_render("shadows", false));
  seen.push_back(layer.revision());
  layer.undo();
  seen.push_back(layer.revision());
  layer.redo();
  seen.push_back(layer.revision());
  for (std::size_t i = 1; i < seen.size(); ++i) EXPECT_GT(seen[i], seen[i - 1]);
}

TEST(CommandLayer, LabelsNameTheEdit) {
  CommandLayer layer(test::two_sphere_scene());
  layer.execute(ApplyPreset{1, "ruby"});
  EXPECT_EQ(layer.undo_label(), "apply preset ruby to object 1");
  layer.undo();
  EXPECT_EQ(layer.redo_label(), "apply preset ruby to object 1");
  EXPECT_EQ(layer.undo_label(), "");
}

TEST(CommandLayer, SaveAsKeepsThePathThroughUndo) {
  CommandLayer layer(test::two_sphere_scene());
  layer.execute(test::set_render("shadows", false));
  layer.set_path("/tmp/elsewhere.json");
  layer.undo();
  EXPECT_EQ(layer.scene().path, "/tmp/elsewhere.json");
}

// Every relative file name follows the document: model files, maps and the environment map (Save
// As used to move the model files only, so a saved copy of the studio scene lost its map).
TEST(CommandLayer, SaveAsRebasesRelativeFiles) {
  Scene scene = test::two_sphere_scene();
  scene.path = "/data/scenes/room.json";
  scene.objects[0].params.file = "../models/cup.obj";
  scene.objects[1].params.file = "/abs/teapot.obj";
  scene.materials[0].map(MapSlot::diffuse).file = "maps/wood.png";
  scene.environment.file = "../environments/studio.exr";
  CommandLayer layer(scene);
  layer.execute(test::set_render("shadows", false));
  layer.set_path("/data/out/copy.json");
  EXPECT_EQ(layer.scene().objects[0].params.file, "../models/cup.obj");  // same depth
  EXPECT_EQ(layer.scene().materials[0].map(MapSlot::diffuse).file, "../scenes/maps/wood.png");
  layer.set_path("/data/copy.json");
  EXPECT_EQ(layer.scene().objects[0].params.file, "models/cup.obj");
  EXPECT_EQ(layer.scene().objects[1].params.file, "/abs/teapot.obj");
  EXPECT_EQ(layer.scene().materials[0].map(MapSlot::diffuse).file, "scenes/maps/wood.png");
  EXPECT_EQ(layer.scene().environment.file, "environments/studio.exr");
  layer.undo();
  EXPECT_EQ(layer.scene().objects[0].params.file, "models/cup.obj");
  EXPECT_EQ(layer.scene().environment.file, "environments/studio.exr");
}

TEST(CommandLayer, HistoryIsBounded) {
  CommandLayer layer(test::two_sphere_scene());
  for (std::size_t i = 0; i < CommandLayer::kMaxSteps + 20; ++i) {
    layer.execute(test::set_render("shadows", i % 2 == 0 ? false : true));
  }
  EXPECT_EQ(layer.undo_count(), CommandLayer::kMaxSteps);
}

// The earlier document before File > Open: the shipped file, untouched (saved), at its path.
Scene shipped_scene() {
  Scene scene = test::two_sphere_scene();
  scene.path = "/usr/share/gloss/assets/scenes/spheres.json";
  return scene;
}

std::shared_ptr<const Scene> other_scene() {
  auto scene = std::make_shared<Scene>(test::two_sphere_scene());
  scene->path = "/home/user/other.json";
  scene->materials[0].shininess = 12.0f;
  return scene;
}

// Undoing "open scene" used to leave the untouched earlier scene marked modified, so "Save and
// quit" would have written it over the shipped file.
TEST(CommandLayer, UndoingAnOpenGivesBackTheUntouchedDocumentUnmodified) {
  CommandLayer layer(shipped_scene());
  EXPECT_TRUE(layer.open_document(other_scene(), "open other.json"));
  EXPECT_FALSE(layer.dirty());
  EXPECT_EQ(layer.undo_label(), "open other.json");
  ASSERT_TRUE(layer.undo());
  EXPECT_EQ(layer.scene().path, "/usr/share/gloss/assets/scenes/spheres.json");
  EXPECT_EQ(layer.scene().materials[0].shininess, 64.0f);
  EXPECT_FALSE(layer.dirty());
  ASSERT_TRUE(layer.redo());
  EXPECT_EQ(layer.scene().path, "/home/user/other.json");
  EXPECT_FALSE(layer.dirty());
}

TEST(CommandLayer, UndoingAnOpenGivesBackAnEditedDocumentModified) {
  CommandLayer layer(shipped_scene());
  layer.execute(test::set_shininess(1, 30.0f));
  ASSERT_TRUE(layer.dirty());
  layer.open_document(other_scene(), "open other.json");
  layer.execute(test::set_render("shadows", false));  // an edit of the opened document
  EXPECT_TRUE(layer.dirty());
  layer.undo();
  EXPECT_FALSE(layer.dirty());  // the opened document as its file holds it
  layer.undo();
  EXPECT_TRUE(layer.dirty());  // the earlier document with its unsaved edit
  EXPECT_EQ(layer.scene().materials[1].shininess, 30.0f);
  layer.undo();
  EXPECT_FALSE(layer.dirty());  // the earlier document as its file holds it
  layer.redo();
  layer.redo();
  EXPECT_FALSE(layer.dirty());
  layer.redo();
  EXPECT_TRUE(layer.dirty());
}

TEST(CommandLayer, SaveAsAfterAnOpenLeavesTheEarlierDocumentsPath) {
  CommandLayer layer(shipped_scene());
  layer.open_document(other_scene(), "open other.json");
  layer.execute(test::set_render("shadows", false));
  layer.set_path("/home/user/copy.json");
  layer.mark_saved();
  layer.undo();
  EXPECT_EQ(layer.scene().path, "/home/user/copy.json");
  layer.undo();
  EXPECT_EQ(layer.scene().path, "/usr/share/gloss/assets/scenes/spheres.json");
  EXPECT_FALSE(layer.dirty());
}

TEST(ExponentRule, BlinnIsFourTimesPhongClampedToTheSliderRange) {
  EXPECT_EQ(blinn_exponent_for_phong(10.0f), 40.0f);
  EXPECT_EQ(phong_exponent_for_blinn(40.0f), 10.0f);
  EXPECT_EQ(blinn_exponent_for_phong(5000.0f), 10000.0f);  // the shininess slider's top
  EXPECT_EQ(exponent_for_model(12.0f, ShadingModel::phong, ShadingModel::phong), 12.0f);
}

}  // namespace
}  // namespace gloss

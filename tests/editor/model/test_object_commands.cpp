// The object and material commands (object_commands.h): what each does to the document, that
// each is one undo step which restores the document exactly, and that a gizmo drag of several
// frames is one step.
#include "editor/model/document/object_commands.h"

#include <gtest/gtest.h>

#include "editor/model/document/command_layer.h"
#include "io/scene/scene_loader.h"
#include "scene/fields/scene_diff.h"
#include "scene/geometry/placement.h"
#include "support/test_scene.h"

namespace gloss {
namespace {

// Applies command as the only edit and checks that undo gives back the scene exactly.
Scene applied(const Scene& scene, const Command& command) {
  CommandLayer layer(scene);
  EXPECT_TRUE(layer.execute(command));
  EXPECT_EQ(layer.undo_count(), 1u);
  Scene after = layer.scene();
  EXPECT_TRUE(layer.undo());
  EXPECT_FALSE(diff_scenes(layer.scene(), scene).any);
  return after;
}

std::string error_of(const Scene& scene, const Command& command) {
  CommandLayer layer(scene);
  try {
    layer.execute(command);
  } catch (const CommandError& e) {
    EXPECT_FALSE(diff_scenes(layer.scene(), scene).any);  // a refusal leaves the document
    return e.what();
  }
  return "";
}

Scene three_spheres() {
  Scene scene = test::two_sphere_scene();  // "left" at x -1.2, "right" at 1.2, radius 1
  scene.objects.push_back(sphere_object("top", {0, 2, 0}, 0.5f, 1));
  return scene;
}

TEST(ObjectCommands, DeleteShiftsTheLaterObjectsDown) {
  const Scene after = applied(three_spheres(), DeleteObjects{{0}});
  ASSERT_EQ(after.objects.size(), 2u);
  EXPECT_EQ(after.objects[0].name, "right");
  EXPECT_EQ(after.objects[1].name, "top");
  EXPECT_EQ(after.materials.size(), 2u);  // materials stay for reuse
  EXPECT_EQ(applied(three_spheres(), DeleteObjects{{2, 0}}).objects[0].name, "right");
  EXPECT_NE(error_of(three_spheres(), DeleteObjects{{3}}).find("no object 3 (the scene has 3)"),
            std::string::npos);
}

TEST(ObjectCommands, DuplicateSharesTheMaterialAndStandsBesideTheOriginal) {
  const Scene after = applied(three_spheres(), DuplicateObjects{{0}});
  ASSERT_EQ(after.objects.size(), 4u);
  const Object& copy = after.objects[3];
  EXPECT_EQ(copy.name, "left 2");
  EXPECT_EQ(copy.material, after.objects[0].material);
  // The camera looks down -z with y up: its right is +x. The sphere is 2 wide: the copy moves
  // 1.1 x 2 = 2.2 to the right.
  EXPECT_FLOAT_EQ(copy.transform.translate.x, 2.2f);
  EXPECT_FLOAT_EQ(copy.center.x, -1.2f + 2.2f);
  EXPECT_EQ(copy.params.center, after.objects[0].params.center);  // its own fields are kept
  // A copy of the copy counts on from the original's name.
  EXPECT_EQ(applied(after, DuplicateObjects{{3}}).objects[4].name, "left 3");
}

TEST(ObjectCommands, HideShowAndSolo) {
  Scene after = applied(three_spheres(), SetHidden{{1}, true});
  EXPECT_FALSE(after.objects[0].hidden);
  EXPECT_TRUE(after.objects[1].hidden);
  after = applied(after, SoloObjects{{1}});
  EXPECT_TRUE(after.objects[0].hidden);
  EXPECT_FALSE(after.objects[1].hidden);  // solo shows what it keeps
  EXPECT_TRUE(after.objects[2].hidden);
  const SceneDiff diff = diff_scenes(three_spheres(), applied(three_spheres(), SetHidden{{2}}));
  EXPECT_TRUE(diff.geometry);  // the Embree scene loses it
}

TEST(ObjectCommands, NamesAreUniqueAndNotEmpty) {
  EXPECT_EQ(applied(three_spheres(), RenameObject{2, "gold ball"}).objects[2].name, "gold ball");
  EXPECT_NE(error_of(three_spheres(), RenameObject{2, "left"}).find("already called 'left'"),
            std::string::npos);
  EXPECT_NE(error_of(three_spheres(), RenameObject{2, ""}).find("must not be empty"),
            std::string::npos);
  EXPECT_EQ(find_object(three_spheres(), "top"), 2);
  EXPECT_EQ(unique_object_name(three_spheres(), "top"), "top 2");
  EXPECT_EQ(unique_object_name(three_spheres(), "box"), "box");
}

TEST(ObjectCommands, MaterialsAreRenamedAssignedAndCopied) {
  Scene after = applied(three_spheres(), RenameMaterial{"red", "polished brass"});
  EXPECT_EQ(after.material_names[0], "polished brass");  // same place: no index changes
  EXPECT_EQ(after.objects[0].material, 0);
  EXPECT_NE(error_of(three_spheres(), RenameMaterial{"red", "blue"}).find("already called"),
            std::string::npos);
  EXPECT_NE(error_of(three_spheres(), RenameMaterial{"gren", "x"}).find("no material called"),
            std::string::npos);
  after = applied(three_spheres(), AssignMaterial{{0, 2}, 1});
  EXPECT_EQ(after.objects[0].material, 1);
  EXPECT_EQ(after.objects[2].material, 1);
  Material gold;
  gold.diffuse = {0.8f, 0.6f, 0.2f};
  after = applied(three_spheres(), NewMaterial{{1}, gold, "red"});
  ASSERT_EQ(after.materials.size(), 3u);
  EXPECT_EQ(after.material_names[2], "red 2");
  EXPECT_EQ(after.objects[1].material, 2);
  EXPECT_EQ(after.materials[2].diffuse, gold.diffuse);
}

TEST(ObjectCommands, ARenamedMaterialSavesAndReloadsWithItsObjects) {
  Scene scene = applied(three_spheres(), RenameMaterial{"red", "zinc"});
  const Scene back = parse_scene(scene_to_json_text(scene), "s.json");
  // The loader orders materials by name: blue, zinc; "left" still has the red constants.
  ASSERT_EQ(back.material_names, (std::vector<std::string>{"blue", "zinc"}));
  EXPECT_EQ(back.material_names[back.objects[0].material], "zinc");
  EXPECT_EQ(back.materials[back.objects[0].material].diffuse, scene.materials[0].diffuse);
}

TEST(ObjectCommands, AGizmoDragIsOneUndoStep) {
  CommandLayer layer(three_spheres());
  for (int frame = 1; frame <= 5; ++frame) {
    ObjectTransform t;
    t.translate = {0.1f * frame, 0, 0};
    t.pivot = layer.scene().objects[0].transform.pivot;
    ObjectTransform u = t;
    u.pivot = layer.scene().objects[2].transform.pivot;
    ASSERT_TRUE(layer.execute(TransformObjects{{0, 2}, {t, u}}));
  }
  EXPECT_EQ(layer.undo_count(), 1u);
  EXPECT_FLOAT_EQ(layer.scene().objects[0].center.x, -1.2f + 0.5f);
  EXPECT_FLOAT_EQ(layer.scene().objects[2].center.x, 0.5f);
  layer.seal();  // the drag ended: the next one is a step of its own
  ObjectTransform t = layer.scene().objects[0].transform;
  t.rotate = {0, 0, 10};
  layer.execute(TransformObjects{{0}, {t}});
  EXPECT_EQ(layer.undo_count(), 2u);
  layer.undo();
  layer.undo();
  EXPECT_FALSE(diff_scenes(layer.scene(), three_spheres()).any);
}

TEST(ObjectCommands, ATransformFieldIsAGeometryChange) {
  CommandLayer layer(three_spheres());
  layer.execute(SetField{FieldPart::transform, 1, "translate", vec3_value({0, 1, 0})});
  layer.execute(SetField{FieldPart::transform, 1, "translate", vec3_value({0, 2, 0})});
  EXPECT_EQ(layer.undo_count(), 1u);  // a numeric field's drag: one step
  EXPECT_EQ(layer.scene().objects[1].center, glm::vec3(1.2f, 2, 0));
  const SceneDiff diff = diff_scenes(three_spheres(), layer.scene());
  EXPECT_TRUE(diff.geometry);
  EXPECT_EQ(diff.change, ChangeClass::full);
  // A sphere takes a uniform scale only; the field's own range is checked too.
  EXPECT_THROW(layer.execute(SetField{FieldPart::transform, 1, "scale", vec3_value({1, 2, 1})}),
               CommandError);
  EXPECT_THROW(layer.execute(SetField{FieldPart::transform, 1, "scale", vec3_value({0, 0, 0})}),
               CommandError);
  EXPECT_THROW(
      layer.execute(SetField{FieldPart::transform, 1, "translate", vec3_value({2e15f, 0, 0})}),
      CommandError);
  layer.execute(SetField{FieldPart::object, 1, "hidden", number_value(1)});
  EXPECT_TRUE(layer.scene().objects[1].hidden);
}

}  // namespace
}  // namespace gloss

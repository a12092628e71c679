// Every command kind, applied through the command layer, changes the document as asked and undo
// restores the earlier document exactly (compared through the scene writer's JSON text, which
// is independent of the layer's own comparison); redo brings the edit back.
#include <gtest/gtest.h>

#include <memory>

#include "editor/model/document/command_layer.h"
#include "io/material/preset_table.h"
#include "io/scene/scene_loader.h"
#include "support/field_commands.h"
#include "support/test_scene.h"

namespace gloss {
namespace {

struct Case {
  const char* name;
  Command command;
  // Checks that the edit did what the command says, on the document after it.
  void (*check)(const Scene& after);
};

std::vector<Case> all_cases() {
  auto opened = std::make_shared<Scene>(test::two_sphere_scene());
  opened->objects.pop_back();
  opened->background = {0.5f, 0.0f, 0.5f};
  PointLight added;
  added.position = {0.0f, 9.0f, 0.0f};
  Camera moved = test::two_sphere_scene().camera;
  moved.eye = {3.0f, 3.0f, 3.0f};
  Material loaded;
  loaded.diffuse = {0.3f, 0.3f, 0.3f};
  loaded.shininess = 7.0f;
  PhysicalReference gold;
  gold.roughness = 0.2f;
  Material fitted = test::two_sphere_scene().materials[0];
  fitted.specular = {200.0f, 150.0f, 70.0f};
  fitted.shininess = 700.0f;
  fitted.reference = gold;
  return {
      {"material colour", test::set_material(1, "diffuse", {0.9f, 0.8f, 0.7f}),
       [](const Scene& s) { EXPECT_EQ(s.materials[1].diffuse, glm::vec3(0.9f, 0.8f, 0.7f)); }},
      {"emission", test::set_material(0, "emission", {0.0f, 0.5f, 0.0f}),
       [](const Scene& s) { EXPECT_EQ(s.materials[0].emission, glm::vec3(0.0f, 0.5f, 0.0f)); }},
      {"shininess", test::set_shininess(0, 1234.5f),
       [](const Scene& s) { EXPECT_EQ(s.materials[0].shininess, 1234.5f); }},
      {"preset", ApplyPreset{1, "silver"},
       [](const Scene& s) {
         // The table's silver row: diffuse 0.50754 each, shininess 0.4 x 128 = 51.2.
         EXPECT_NEAR(s.materials[1].diffuse.x, 0.50754f, 1e-6f);
         EXPECT_NEAR(s.materials[1].shininess, 51.2f, 1e-4f);
         EXPECT_EQ(s.materials[1].preset, "silver");
       }},
      {"material from a file", SetMaterial{0, loaded, "grey"},
       [](const Scene& s) { EXPECT_EQ(s.materials[0].shininess, 7.0f); }},
      {"model, keeping the highlight size", SetModel{ShadingModel::blinn_phong, true},
       [](const Scene& s) {
         EXPECT_EQ(s.render.model, ShadingModel::blinn_phong);
         EXPECT_EQ(s.materials[0].shininess, 256.0f);  // 4 x 64
         EXPECT_EQ(s.materials[1].shininess, 40.0f);   // 4 x 10
       }},
      {"model, same exponents", SetModel{ShadingModel::blinn_phong, false},
       [](const Scene& s) { EXPECT_EQ(s.materials[0].shininess, 64.0f); }},
      {"energy normalisation", test::set_render("energy_normalize", true),
       [](const Scene& s) { EXPECT_TRUE(s.render.energy_normalize); }},
      {"light position", test::set_light(1, "position", {1.0f, 2.0f, 3.0f}),
       [](const Scene& s) { EXPECT_EQ(s.lights[1].position, glm::vec3(1.0f, 2.0f, 3.0f)); }},
      {"light attenuation", test::set_light(0, "attenuation", {1.0f, 0.5f, 0.25f}),
       [](const Scene& s) { EXPECT_EQ(s.lights[0].attenuation, glm::vec3(1.0f, 0.5f, 0.25f)); }},
      {"add light", AddLight{added},
       [](const Scene& s) {
         ASSERT_EQ(s.lights.size(), 3u);
         EXPECT_EQ(s.lights[2].position.y, 9.0f);
       }},
      {"remove light", RemoveLight{0},
       [](const Scene& s) {
         ASSERT_EQ(s.lights.size(), 1u);
         EXPECT_EQ(s.lights[0].position, glm::vec3(-4.0f, 2.0f, 1.0f));
       }},
      {"scene ambient", test::set_scene("ambient", {0.0f, 0.3f, 0.0f}),
       [](const Scene& s) { EXPECT_EQ(s.ambient, glm::vec3(0.0f, 0.3f, 0.0f)); }},
      {"background", test::set_scene("background", {1.0f, 1.0f, 1.0f}),
       [](const Scene& s) { EXPECT_EQ(s.background, glm::vec3(1.0f)); }},
      {"shadows", test::set_render("shadows", false),
       [](const Scene& s) { EXPECT_FALSE(s.render.shadows); }},
      {"camera", SetCamera{moved},
       [](const Scene& s) { EXPECT_EQ(s.camera.eye, glm::vec3(3.0f)); }},
      {"camera orbit", OrbitCamera{90.0f, 0.0f},
       [](const Scene& s) {
         // A quarter turn about up keeps the distance to the target (sqrt(37)).
         EXPECT_NEAR(glm::length(s.camera.eye - s.camera.target), std::sqrt(37.0f), 1e-4f);
         EXPECT_NEAR(s.camera.eye.z, 0.0f, 1e-4f);
       }},
      {"target spp", test::set_render("spp", 16),
       [](const Scene& s) { EXPECT_EQ(s.render.spp, 16); }},
      {"physical reference", SetReference{1, gold},
       [](const Scene& s) {
         ASSERT_TRUE(s.materials[1].reference.has_value());
         EXPECT_EQ(s.materials[1].reference->roughness, 0.2f);
         EXPECT_FALSE(s.materials[0].reference.has_value());
       }},
      {"a fit and the model switch in one step",
       ApplyFit{0, fitted, ShadingModel::blinn_phong, "fit Blinn-Phong to gold r 0.2"},
       [](const Scene& s) {
         EXPECT_EQ(s.materials[0].shininess, 700.0f);
         EXPECT_EQ(s.materials[0].specular, glm::vec3(200.0f, 150.0f, 70.0f));
         EXPECT_EQ(s.render.model, ShadingModel::blinn_phong);
         EXPECT_EQ(s.materials[1].shininess, 10.0f);  // other materials untouched
       }},
      {"open scene", ReplaceScene{opened, "open"},
       [](const Scene& s) { EXPECT_EQ(s.objects.size(), 1u); }},
  };
}

TEST(CommandsUndo, EveryCommandUndoesExactlyAndRedoes) {
  for (const Case& c : all_cases()) {
    SCOPED_TRACE(c.name);
    const Scene base = test::two_sphere_scene();
    const std::string before = scene_to_json_text(base);
    CommandLayer layer(base);
    ASSERT_TRUE(layer.execute(c.command));
    c.check(layer.scene());
    const std::string after = scene_to_json_text(layer.scene());
    EXPECT_NE(after, before);
    ASSERT_TRUE(layer.undo());
    EXPECT_EQ(scene_to_json_text(layer.scene()), before);
    EXPECT_TRUE(same_scene(layer.scene(), base));
    ASSERT_TRUE(layer.redo());
    EXPECT_EQ(scene_to_json_text(layer.scene()), after);
  }
}

// A reference's fields are set through the field table like any other part, once it has one.
TEST(CommandsUndo, ReferenceFieldsNeedAReference) {
  CommandLayer layer(test::two_sphere_scene());
  FieldValue rough;
  rough.x = 0.5;
  try {
    layer.execute(SetField{FieldPart::reference, 0, "roughness", rough});
    FAIL() << "no error";
  } catch (const CommandError& e) {
    EXPECT_NE(std::string(e.what()).find("has no physical reference"), std::string::npos)
        << e.what();
  }
  ASSERT_TRUE(layer.execute(SetReference{0, PhysicalReference{}}));
  layer.seal();
  ASSERT_TRUE(layer.execute(SetField{FieldPart::reference, 0, "roughness", rough}));
  layer.seal();
  EXPECT_EQ(layer.scene().materials[0].reference->roughness, 0.5f);
  EXPECT_THROW(layer.execute(SetField{FieldPart::reference, 0, "roughness", FieldValue{}}),
               CommandError);  // roughness 0 is outside (0, 1]
  ASSERT_TRUE(layer.undo());
  EXPECT_EQ(layer.scene().materials[0].reference->roughness, 0.3f);
  ASSERT_TRUE(layer.execute(SetReference{0, std::nullopt}));
  EXPECT_FALSE(layer.scene().materials[0].reference.has_value());
}

TEST(CommandsUndo, AllCommandsInSequenceUndoBackToTheStart) {
  const Scene base = test::two_sphere_scene();
  CommandLayer layer(base);
  std::vector<std::string> states{scene_to_json_text(base)};
  for (const Case& c : all_cases()) {
    if (layer.execute(c.command)) {
      layer.seal();
      states.push_back(scene_to_json_text(layer.scene()));
    }
  }
  for (std::size_t i = states.size() - 1; i > 0; --i) {
    EXPECT_EQ(scene_to_json_text(layer.scene()), states[i]);
    ASSERT_TRUE(layer.undo());
  }
  EXPECT_EQ(scene_to_json_text(layer.scene()), states[0]);
  EXPECT_FALSE(layer.can_undo());
}

}  // namespace
}  // namespace gloss

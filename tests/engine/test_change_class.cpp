// Every kind of edit falls in the class that invalidates just enough.
#include "engine/change_class.h"

#include <gtest/gtest.h>

#include "support/scene_fixtures.h"

namespace gloss {
namespace {

class ChangeClassTest : public ::testing::Test {
 protected:
  Scene before = test::head_on_sphere_scene();
  Scene after = before;
  ChangeClass change() const { return classify_change(before, after); }
};

TEST_F(ChangeClassTest, NothingChangedIsNone) {
  EXPECT_EQ(change(), ChangeClass::none);
}

TEST_F(ChangeClassTest, MaterialConstantsAreShade) {
  after.materials[0].diffuse = {0.1f, 0.2f, 0.3f};
  EXPECT_EQ(change(), ChangeClass::shade);
  after = before;
  after.materials[0].emission = glm::vec3(0.5f);
  EXPECT_EQ(change(), ChangeClass::shade);
}

TEST_F(ChangeClassTest, LightColoursAmbientBackgroundAndEnergySwitchAreShade) {
  after.lights[0].specular = glm::vec3(0.3f);
  EXPECT_EQ(change(), ChangeClass::shade);
  after = before;
  after.ambient = glm::vec3(0.5f);
  after.background = glm::vec3(1.0f);
  after.render.energy_normalize = true;
  EXPECT_EQ(change(), ChangeClass::shade);
}

TEST_F(ChangeClassTest, ShininessModelAndMaterialAssignmentAreExponent) {
  after.materials[0].shininess = 200;
  EXPECT_EQ(change(), ChangeClass::exponent);
  after = before;
  after.render.model = ShadingModel::blinn_phong;
  EXPECT_EQ(change(), ChangeClass::exponent);
  after = before;
  test::add_material(after, "other", after.materials[0]);
  after.objects[0].material = 1;
  EXPECT_EQ(change(), ChangeClass::exponent);
}

TEST_F(ChangeClassTest, LightPositionAttenuationCountAndShadowsAreLight) {
  after.lights[0].position = {1, 2, 3};
  EXPECT_EQ(change(), ChangeClass::light);
  after = before;
  after.lights[0].attenuation = {1, 0, 0};
  EXPECT_EQ(change(), ChangeClass::light);
  after = before;
  after.lights.push_back(test::make_light({0, 0, 9}));
  EXPECT_EQ(change(), ChangeClass::light);
  after = before;
  after.render.shadows = false;
  EXPECT_EQ(change(), ChangeClass::light);
}

TEST_F(ChangeClassTest, ColourEditThatChangesThePlanIsLight) {
  // A black light is not traced; lighting it up needs its factors and shadow rays.
  before.lights[0].diffuse = before.lights[0].specular = glm::vec3(0.0f);
  after = before;
  after.lights[0].diffuse = glm::vec3(1.0f);
  EXPECT_EQ(change(), ChangeClass::light);
}

TEST_F(ChangeClassTest, CameraGeometryResolutionAndSppAreFull) {
  after.camera.eye = {0, 1, 5};
  EXPECT_EQ(change(), ChangeClass::full);
  after = before;
  after.objects[0].radius = 2;
  EXPECT_EQ(change(), ChangeClass::full);
  after = before;
  after.render.width = 64;
  EXPECT_EQ(change(), ChangeClass::full);
  after = before;
  after.render.spp = 16;
  EXPECT_EQ(change(), ChangeClass::full);
  after = before;
  test::add_sphere(after, {3, 0, 0}, 1, 0);
  EXPECT_EQ(change(), ChangeClass::full);
}

}  // namespace
}  // namespace gloss

// The environment light and the light types in the editor's model: SetEnvironment and the
// environment's fields through the command layer (a shipped map by name, a file, off, a bad
// file refused with the scene kept, undo), the script lines that make them, and the viewport's
// light handles (light_gizmo.h) with values worked by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "base/error.h"
#include "editor/model/document/command_layer.h"
#include "editor/model/script/script.h"
#include "editor/model/view/light_gizmo.h"
#include "io/scene/scene_loader.h"

namespace gloss {
namespace {

Scene plain_scene() {
  return parse_scene(R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0]},
    "lights": [{"position": [2, 3, 4]}],
    "materials": {"m": {"preset": "gold"}},
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})",
                     "plain.json");
}

Command command_of(const std::string& line) {
  const Script script = parse_script(line + "\n", "t.txt");
  return std::get<Command>(script.lines.at(0).action);
}

TEST(EnvironmentCommand, ShippedMapFieldsOffAndUndo) {
  CommandLayer layer(plain_scene());
  // No environment yet: its fields have nothing to set.
  EXPECT_THROW(layer.execute(command_of("environment rotation 30")), CommandError);
  ASSERT_TRUE(layer.execute(command_of("environment studio")));
  const Environment& e = layer.scene().environment;
  ASSERT_TRUE(e.present());
  EXPECT_EQ(e.map->radiance.width, 2 * e.map->radiance.height);  // equirectangular
  ASSERT_TRUE(layer.execute(command_of("environment rotation 30")));
  ASSERT_TRUE(layer.execute(command_of("environment intensity 0.5")));
  ASSERT_TRUE(layer.execute(command_of("environment background off")));
  EXPECT_FLOAT_EQ(layer.scene().environment.rotation, 30.0f);
  EXPECT_FLOAT_EQ(layer.scene().environment.intensity, 0.5f);
  EXPECT_FALSE(layer.scene().environment.as_background);
  // Another map keeps the numbers.
  const auto studio = layer.scene().environment.map;
  ASSERT_TRUE(layer.execute(command_of("environment sunset")));
  EXPECT_NE(layer.scene().environment.map, studio);
  EXPECT_FLOAT_EQ(layer.scene().environment.rotation, 30.0f);
  ASSERT_TRUE(layer.execute(command_of("environment off")));
  EXPECT_FALSE(layer.scene().environment.present());
  EXPECT_TRUE(layer.scene().environment.file.empty());
  ASSERT_TRUE(layer.undo());
  EXPECT_EQ(layer.scene().environment.map != nullptr, true);
  EXPECT_NE(layer.scene().environment.map, studio);  // the sunset map again
}

TEST(EnvironmentCommand, BadFileIsOneErrorAndTheSceneIsKept) {
  CommandLayer layer(plain_scene());
  ASSERT_TRUE(layer.execute(command_of("environment studio")));
  const auto map = layer.scene().environment.map;
  try {
    layer.execute(SetEnvironment{"/nonexistent/none.exr"});
    FAIL() << "a missing map was accepted";
  } catch (const CommandError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/none.exr"), std::string::npos) << e.what();
  }
  EXPECT_EQ(layer.scene().environment.map, map);
  // Not an image: this very source file.
  EXPECT_THROW(layer.execute(SetEnvironment{__FILE__}), CommandError);
  EXPECT_EQ(layer.scene().environment.map, map);
  EXPECT_THROW(layer.execute(command_of("environment intensity -1")), CommandError);
}

TEST(EnvironmentCommand, LightTypeLines) {
  CommandLayer layer(plain_scene());
  ASSERT_TRUE(layer.execute(command_of("light 0 type spot")));
  ASSERT_TRUE(layer.execute(command_of("light 0 direction 0 -1 -1")));
  ASSERT_TRUE(layer.execute(command_of("light 0 cutoff 20")));
  EXPECT_EQ(layer.scene().lights[0].type, LightType::spot);
  EXPECT_FLOAT_EQ(layer.scene().lights[0].cutoff, 20.0f);
  EXPECT_THROW(parse_script("light 0 type sun\n", "t.txt"), InputError);
}

// Camera at (0, 0, 5) looking at the origin: right +x, up +y, forward -z.
Camera front_camera() {
  Camera c;
  c.eye = {0, 0, 5};
  c.target = {0, 0, 0};
  return c;
}

TEST(LightGizmo, HandlesSitWhereTheDirectionSays) {
  Light spot;
  spot.type = LightType::spot;
  spot.position = {0, 4, 0};
  spot.direction = {0, -2, 0};  // any length
  spot.cutoff = 45.0f;
  const LightGizmo g = light_gizmo(spot, front_camera());
  // Half way to the target (distance 4): the handle at (0, 2, 0), the rim's radius 2 tan 45.
  EXPECT_NEAR(g.length, 2.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(g.handle, glm::vec3(0, 2, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(g.cone_radius, 2.0f, 1e-5f);
  Light sun;
  sun.type = LightType::directional;
  sun.direction = {0, -1, 0};
  const LightGizmo d = light_gizmo(sun, front_camera());
  EXPECT_FALSE(d.positioned);
  // 0.35 of the view distance (5) above the target: the light comes down onto it.
  EXPECT_NEAR(glm::distance(d.handle, glm::vec3(0, 1.75f, 0)), 0.0f, 1e-6f);
}

TEST(LightGizmo, DraggingAHandleAims) {
  const Camera camera = front_camera();
  Light spot;
  spot.type = LightType::spot;
  spot.position = {0, 4, 0};
  // A handle dragged to (3, 0, 0): from (0, 4, 0) the way is (3, -4, 0) / 5.
  const glm::vec3 d = direction_for_handle(spot, camera, {3, 0, 0});
  EXPECT_NEAR(d.x, 0.6f, 1e-6f);
  EXPECT_NEAR(d.y, -0.8f, 1e-6f);
  Light sun;
  sun.type = LightType::directional;
  // The arrow's tail dragged to (0, 0, 2): the light travels from there to the target, -z.
  glm::vec3 s = direction_for_handle(sun, camera, {0, 0, 2});
  EXPECT_NEAR(s.z, -1.0f, 1e-6f);
  // A headlight keeps camera space: world -z is straight ahead, (0, 0, -1) there too; world +x
  // is the camera's right, (1, 0, 0).
  sun.follow_camera = true;
  s = direction_for_handle(sun, camera, {-2, 0, 0});
  EXPECT_NEAR(s.x, 1.0f, 1e-6f);
  EXPECT_NEAR(std::abs(s.y) + std::abs(s.z), 0.0f, 1e-6f);
}

TEST(LightGizmo, OrbitTurnsDirectionalLightsAboutUp) {
  Light sun;
  sun.type = LightType::directional;
  sun.direction = {1, -1, 0};
  // 90 degrees counter-clockwise seen from above: +x goes to -z.
  const Light turned = orbited_light(sun, glm::vec3(0.0f), 90.0f);
  EXPECT_NEAR(turned.direction.x, 0.0f, 1e-6f);
  EXPECT_NEAR(turned.direction.y, -1.0f, 1e-6f);
  EXPECT_NEAR(turned.direction.z, -1.0f, 1e-6f);
  EXPECT_EQ(turned.position, sun.position);
  sun.follow_camera = true;  // a headlight turns with the camera, not with the orbit
  EXPECT_EQ(orbited_light(sun, glm::vec3(0.0f), 90.0f).direction, sun.direction);
  Light spot;
  spot.type = LightType::spot;
  spot.position = {2, 3, 0};
  spot.direction = {-1, -1, 0};
  const Light s = orbited_light(spot, glm::vec3(0.0f), 90.0f);
  EXPECT_NEAR(glm::distance(s.position, glm::vec3(0, 3, -2)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(s.direction, glm::vec3(0, -1, 1)), 0.0f, 1e-5f);
}

}  // namespace
}  // namespace gloss

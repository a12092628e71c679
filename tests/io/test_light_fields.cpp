// Lights' types in scene files (docs/spec/scene-and-cli.md): what each type requires, the
// documented defaults, the refusals (zero direction, a cone outside (0, 90], an unknown type),
// and the writer: an old point light's keys stay as they were, a light switched to another type
// keeps the fields it no longer uses, and everything reads back exactly.
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "base/error.h"
#include "io/scene/scene_loader.h"

namespace gloss {
namespace {

std::string scene_with_lights(const std::string& lights) {
  return R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0]},
             "lights": [)" +
         lights + R"(], "materials": {"m": {"preset": "gold"}},
             "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}],
             "render": {"width": 32, "height": 24}})";
}

std::string error_of(const std::string& lights) {
  try {
    parse_scene(scene_with_lights(lights), "lights.json");
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "accepted: " << lights;
  return "";
}

TEST(LightFields, AnOldPointLightReadsAsBefore) {
  const Scene scene = parse_scene(scene_with_lights(R"({"position": [3, 3, 3]})"), "a.json");
  ASSERT_EQ(scene.lights.size(), 1u);
  const Light& light = scene.lights[0];
  EXPECT_EQ(light.type, LightType::point);
  EXPECT_EQ(light.position, glm::vec3(3.0f));
  // The documented defaults of the fields a point light ignores.
  EXPECT_EQ(light.direction, glm::vec3(0.0f, -1.0f, 0.0f));
  EXPECT_EQ(light.cutoff, 45.0f);
  EXPECT_EQ(light.inner, 90.0f);  // min(inner, cutoff) = cutoff: a hard edge
  EXPECT_EQ(light.exponent, 0.0f);
  EXPECT_FALSE(light.follow_camera);
  // Written back with the keys it was written with before light types existed, and its type.
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(scene_to_json_text(scene));
  std::vector<std::string> keys;
  for (const auto& item : j["lights"][0].items()) keys.push_back(item.key());
  const std::vector<std::string> old_keys = {"type",    "position", "ambient",
                                             "diffuse", "specular", "attenuation"};
  EXPECT_EQ(keys, old_keys);
}

TEST(LightFields, ADirectionalLightNeedsNoPositionAndAPointLightDoes) {
  const Scene scene =
      parse_scene(scene_with_lights(R"({"type": "directional", "direction": [0, 0, -1],
                            "follow_camera": true})"),
                  "a.json");
  EXPECT_EQ(scene.lights[0].type, LightType::directional);
  EXPECT_TRUE(scene.lights[0].follow_camera);
  const std::string point = error_of(R"({"diffuse": [1, 1, 1]})");
  EXPECT_NE(point.find("lights[0].position: missing required field"), std::string::npos) << point;
  const std::string spot = error_of(R"({"type": "spot", "direction": [0, -1, 0]})");
  EXPECT_NE(spot.find("lights[0].position: missing required field"), std::string::npos) << spot;
}

TEST(LightFields, BadValuesAreRefusedNamingTheField) {
  EXPECT_NE(error_of(R"({"type": "spot", "position": [0, 2, 0], "direction": [0, 0, 0]})")
                .find("lights[0].direction: must not be [0, 0, 0]"),
            std::string::npos);
  for (const char* cutoff : {"0", "-1", "90.5"}) {
    const std::string e = error_of(std::string(R"({"type": "spot", "position": [0, 2, 0],
                                                   "cutoff": )") +
                                   cutoff + "}");
    EXPECT_NE(e.find("lights[0].cutoff"), std::string::npos) << e;
  }
  const std::string e = error_of(R"({"type": "spot", "position": [0, 2, 0], "exponent": -2})");
  EXPECT_NE(e.find("lights[0].exponent"), std::string::npos) << e;
  const std::string type = error_of(R"({"type": "sun", "direction": [0, -1, 0]})");
  EXPECT_NE(type.find("lights[0].type"), std::string::npos) << type;
  EXPECT_NE(type.find("did you mean 'spot'"), std::string::npos) << type;
  // A cutoff of exactly 90 is the widest cone allowed.
  EXPECT_NO_THROW(parse_scene(scene_with_lights(R"({"type": "spot", "position": [0, 2, 0],
                                                    "cutoff": 90})"),
                              "a.json"));
}

TEST(LightFields, ALightSwitchedToAnotherTypeKeepsWhatItNoLongerUses) {
  Scene scene = parse_scene(
      scene_with_lights(R"({"type": "spot", "position": [1, 2, 3], "direction": [0, -1, 0.5],
                            "cutoff": 20, "inner": 10, "exponent": 4,
                            "attenuation": [1, 0.1, 0.01]})"),
      "a.json");
  scene.lights[0].type = LightType::directional;
  const Scene again = parse_scene(scene_to_json_text(scene), "a.json");
  const Light& l = again.lights[0];
  EXPECT_EQ(l.type, LightType::directional);
  EXPECT_EQ(l.position, glm::vec3(1.0f, 2.0f, 3.0f));
  EXPECT_EQ(l.cutoff, 20.0f);
  EXPECT_EQ(l.inner, 10.0f);
  EXPECT_EQ(l.exponent, 4.0f);
  EXPECT_EQ(l.attenuation, glm::vec3(1.0f, 0.1f, 0.01f));
  EXPECT_EQ(l, scene.lights[0]);
  // And back to a spot, as it was.
  Scene back = again;
  back.lights[0].type = LightType::spot;
  EXPECT_EQ(parse_scene(scene_to_json_text(back), "a.json").lights[0].cutoff, 20.0f);
}

}  // namespace
}  // namespace gloss

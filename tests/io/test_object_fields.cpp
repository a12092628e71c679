// An object's `transform` and `hidden` in scene files (docs/scene-format.md): read and written
// through their field tables, exact round trips, refusals naming the field, and old scenes that
// read exactly as before.
#include <string>

#include <gtest/gtest.h>

#include "base/error.h"
#include "io/scene/scene_loader.h"
#include "scene/fields/fields.h"

namespace gloss {
namespace {

std::string scene_with(const std::string& objects) {
  return R"({"materials": {"m": {}}, "objects": [)" + objects + "]}";
}

std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "s.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ObjectFields, TransformAndHiddenAreReadFromTheirTables) {
  const Scene scene = parse_scene(
      scene_with(R"({"type": "sphere", "center": [1, 2, 3], "radius": 0.5, "material": "m",
        "hidden": true, "transform": {"translate": [1, 0, 0], "rotate": [0, 90, 0],
        "scale": 2}},
        {"type": "box", "min": [0, 0, 0], "max": [2, 2, 2], "material": "m",
         "transform": {"scale": [1, 3, 1], "pivot": [0, 0, 0]}})"),
      "s.json");
  const Object& ball = scene.objects[0];
  EXPECT_TRUE(ball.hidden);
  EXPECT_EQ(ball.transform.translate, glm::vec3(1, 0, 0));
  EXPECT_EQ(ball.transform.rotate, glm::vec3(0, 90, 0));
  EXPECT_EQ(ball.transform.scale, glm::vec3(2, 2, 2));  // one number for all three axes
  EXPECT_FALSE(ball.transform.pivot_set);
  EXPECT_EQ(ball.center, glm::vec3(2, 2, 3));  // placed: centre + translate
  EXPECT_EQ(ball.radius, 1.0f);
  const Object& box = scene.objects[1];
  EXPECT_FALSE(box.hidden);
  EXPECT_TRUE(box.transform.pivot_set);
  glm::vec3 lo, hi;
  ASSERT_TRUE(mesh_bounds(*box.mesh, lo, hi));
  EXPECT_EQ(lo, glm::vec3(0, 0, 0));  // y scaled by 3 about the pivot at the origin
  EXPECT_EQ(hi, glm::vec3(2, 6, 2));
}

TEST(ObjectFields, WritesOnlyWhatDiffersFromTheIdentityAndReadsBackEqual) {
  const std::string text = scene_with(
      R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"},
         {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m", "hidden": true,
          "transform": {"translate": [0.1, 0, 0], "scale": 0.3}},
         {"type": "quad", "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]],
          "material": "m", "transform": {"rotate": [0, 0, 45], "scale": [1, 2, 1],
          "pivot": [0, 0, 0]}})");
  const Scene scene = parse_scene(text, "s.json");
  const std::string written = scene_to_json_text(scene);
  // The plain sphere has no transform block and no hidden key; the others only their own keys.
  EXPECT_NE(written.find(R"("name": "sphere0", "center": [0, 0, 0], "radius": 1, "material": "m")"),
            std::string::npos)
      << written;
  EXPECT_NE(written.find(R"("transform": {"translate": [0.1, 0, 0], "scale": 0.3},)"),
            std::string::npos)
      << written;
  EXPECT_NE(written.find(R"("hidden": true,)"), std::string::npos) << written;
  EXPECT_EQ(written.find(R"("hidden": false)"), std::string::npos) << written;
  EXPECT_NE(written.find(
                R"("transform": {"rotate": [0, 0, 45], "scale": [1, 2, 1], "pivot": [0, 0, 0]})"),
            std::string::npos)
      << written;
  const Scene back = parse_scene(written, "s.json");
  ASSERT_EQ(back.objects.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back.objects[i].transform, scene.objects[i].transform) << i;
    EXPECT_EQ(back.objects[i].hidden, scene.objects[i].hidden) << i;
    EXPECT_EQ(back.objects[i].center, scene.objects[i].center) << i;
  }
  EXPECT_EQ(back.objects[2].mesh->positions, scene.objects[2].mesh->positions);
  EXPECT_EQ(scene_to_json_text(back), written);
}

TEST(ObjectFields, RefusalsNameTheField) {
  EXPECT_NE(error_of(scene_with(R"({"type": "box", "min": [0, 0, 0], "max": [1, 1, 1],
      "material": "m", "transform": {"scale": [1, 0, 1]}})"))
                .find("objects[0].transform.scale: must not be 0 on any axis"),
            std::string::npos);
  // A sphere scaled by 0: the scale the user typed is named, not the placed radius (0).
  EXPECT_NE(error_of(scene_with(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
      "material": "m", "transform": {"scale": 0}})"))
                .find("objects[0].transform.scale: must not be 0 on any axis"),
            std::string::npos);
  EXPECT_NE(error_of(scene_with(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
      "material": "m", "transform": {"scale": [1, 2, 1]}})"))
                .find("objects[0].transform.scale: a sphere takes a uniform scale only"),
            std::string::npos);
  EXPECT_NE(error_of(scene_with(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
      "material": "m", "transform": {"rotation": [0, 1, 0]}})"))
                .find("objects[0].transform.rotation: unknown key 'rotation' (did you mean "
                      "'rotate'?)"),
            std::string::npos);
  EXPECT_NE(error_of(scene_with(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
      "material": "m", "hidden": "yes"})"))
                .find("objects[0].hidden"),
            std::string::npos);
  EXPECT_NE(error_of(scene_with(R"({"type": "quad", "vertices": [[0, 0, 0], [1, 0, 0],
      [1, 1, 0], [0, 1, 0]], "material": "m", "transform": {"scale": 1e14,
      "translate": [1e15, 0, 0]}})"))
                .find("objects[0].transform: placed vertices reach"),
            std::string::npos);
}

TEST(ObjectFields, TheTablesNameEveryKeyOnce) {
  EXPECT_EQ(field_keys(transform_fields()),
            (std::vector<std::string>{"translate", "rotate", "scale", "pivot"}));
  EXPECT_EQ(field_keys(object_fields()), (std::vector<std::string>{"hidden"}));
  for (const auto& f : transform_fields()) EXPECT_EQ(f.change, ChangeClass::full) << f.key;
}

}  // namespace
}  // namespace gloss

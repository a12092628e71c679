// SetTessellation (editor/model/document/command.h): the teapot's mesh resolution as a live,
// undoable edit. The mesh it makes must be the one the scene reader makes from a file that asks for
// the same tessellation (an independent path: JSON through io/scene/scene_loader), undo must bring
// back the very mesh it replaced, and bad requests must leave the document alone.
#include <gtest/gtest.h>

#include <string>

#include "editor/model/document/command_layer.h"
#include "editor/model/script/script.h"
#include "io/scene/scene_loader.h"

namespace gloss {
namespace {

const char* const kTeapotScene = R"({
  "camera": {"eye": [0, 4, 11], "target": [0, 1.3, 0]},
  "lights": [{"position": [5, 8, 6]}],
  "materials": {"copper": {"preset": "copper"}},
  "objects": [
    {"type": "teapot", "tessellation": %d, "rotate_y": -20, "position": [0.5, 0, 0],
     "scale": [1, 1.2, 1], "material": "copper"},
    {"type": "sphere", "center": [3, 1, 0], "radius": 1, "material": "copper"}]})";

Scene teapot_scene(int level) {
  char text[1024];
  std::snprintf(text, sizeof text, kTeapotScene, level);
  return parse_scene(text, "teapot-" + std::to_string(level) + ".json");
}

TEST(TessellationCommand, MakesTheMeshTheReaderMakes) {
  CommandLayer layer(teapot_scene(8));
  ASSERT_TRUE(layer.execute(SetTessellation{3}));
  const Scene expected = teapot_scene(3);
  const Mesh& got = *layer.scene().objects[0].mesh;
  const Mesh& want = *expected.objects[0].mesh;
  EXPECT_EQ(layer.scene().objects[0].params.tessellation, 3);
  // 32 patches x 2 x 3^2 = 576 triangles before the reader drops the degenerate ones at the
  // lid's and bottom's poles; both paths must drop the same.
  EXPECT_LE(got.triangles.size(), 576u);
  ASSERT_EQ(got.triangles.size(), want.triangles.size());
  ASSERT_EQ(got.positions.size(), want.positions.size());
  for (std::size_t i = 0; i < got.positions.size(); ++i) {
    EXPECT_EQ(got.positions[i], want.positions[i]) << i;
    EXPECT_EQ(got.normals[i], want.normals[i]) << i;
  }
  // The sphere is untouched.
  EXPECT_EQ(layer.scene().objects[1].radius, 1.0f);
}

TEST(TessellationCommand, UndoBringsBackTheSameMesh) {
  const Scene base = teapot_scene(8);
  CommandLayer layer(base);
  const Mesh* before = layer.scene().objects[0].mesh.get();
  ASSERT_TRUE(layer.execute(SetTessellation{16}));
  EXPECT_NE(layer.scene().objects[0].mesh.get(), before);
  layer.seal();
  ASSERT_TRUE(layer.undo());
  EXPECT_EQ(layer.scene().objects[0].mesh.get(), before);
  EXPECT_EQ(layer.scene().objects[0].params.tessellation, 8);
  EXPECT_EQ(scene_to_json_text(layer.scene()), scene_to_json_text(base));
}

TEST(TessellationCommand, BadRequestsLeaveTheDocumentAlone) {
  Scene scene = teapot_scene(8);
  EXPECT_THROW(apply_command(SetTessellation{0}, scene), CommandError);
  EXPECT_THROW(apply_command(SetTessellation{65}, scene), CommandError);
  EXPECT_EQ(scene.objects[0].params.tessellation, 8);
  scene.objects.erase(scene.objects.begin());  // only the sphere left
  EXPECT_THROW(apply_command(SetTessellation{4}, scene), CommandError);
}

TEST(TessellationCommand, ScriptLineAndLabel) {
  const Script s = parse_script("tessellation 5\n", "t.txt");
  ASSERT_EQ(s.lines.size(), 1u);
  const Command& c = std::get<Command>(s.lines[0].action);
  EXPECT_EQ(std::get<SetTessellation>(c).level, 5);
  EXPECT_EQ(command_label(c), "set teapot tessellation to 5");
  EXPECT_EQ(merge_key(c), "tessellation");
  EXPECT_THROW(parse_script("tessellation 2.5\n", "t.txt"), std::exception);
}

}  // namespace
}  // namespace gloss

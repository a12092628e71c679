// Names are bytes: whatever a reader accepts, both JSON writers write back, and the readers give
// the same bytes again (io/json/name_escape.h, docs/spec/scene-and-cli.md "Names").
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "base/error.h"
#include "io/image/image_io.h"
#include "io/json/name_escape.h"
#include "io/material/material_io.h"
#include "io/scene/recovery_file.h"
#include "io/scene/scene_loader.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

// Latin-1 "Terrain\xE6k" as in the OBJ corpus, a lone continuation byte, a name that already
// looks like an escape, a backslash before an escaped byte, and control characters.
const std::vector<std::string> kAwkwardNames = {
    "Terrain\xE6k",    "\x80",           "a\\xE6", "\\\xFF",
    "tab\tand\x1b[0m", "plain \xC3\xA6", "\\x5C",  std::string("nul\0byte", 8)};

TEST(NameEscape, EscapesBytesThatAreNotUtf8AndBackslashesThatLookLikeEscapes) {
  EXPECT_EQ(escape_name("Terrain\xE6k"), "Terrain\\xE6k");
  EXPECT_EQ(escape_name("a\\xE6"), "a\\x5CxE6");
  EXPECT_EQ(escape_name("a\\b \\x \\xG1"), "a\\b \\x \\xG1");  // not followed by two hex digits
  EXPECT_EQ(escape_name("plain \xC3\xA6"), "plain \xC3\xA6");
  EXPECT_EQ(unescape_name("Terrain\\xe6k"), "Terrain\xE6k");
}

TEST(NameEscape, UnescapeUndoesEscapeForAwkwardNames) {
  for (const std::string& name : kAwkwardNames) EXPECT_EQ(unescape_name(escape_name(name)), name);
}

TEST(NameBytes, MtlNameThatIsNotUtf8SurvivesTheMaterialsJsonAndMtlWriters) {
  ScratchFolder folder;
  std::ofstream(folder.file("in.mtl"), std::ios::binary) << "newmtl Terrain\xE6k\nKd 0.5 0.25 0\n";
  const std::vector<NamedMaterial> loaded = load_mtl(folder.file("in.mtl"));
  ASSERT_EQ(loaded.size(), 1u);
  ASSERT_EQ(loaded[0].first, "Terrain\xE6k");

  save_materials_json(folder.file("out.json"), loaded);
  const std::vector<NamedMaterial> from_json = load_materials_json(folder.file("out.json"));
  ASSERT_EQ(from_json.size(), 1u);
  EXPECT_EQ(from_json[0].first, "Terrain\xE6k");
  EXPECT_EQ(from_json[0].second.diffuse, glm::vec3(0.5f, 0.25f, 0.0f));

  save_mtl(folder.file("out.mtl"), from_json);
  EXPECT_EQ(load_mtl(folder.file("out.mtl"))[0].first, "Terrain\xE6k");
}

TEST(NameBytes, EveryAwkwardNameSurvivesTheMaterialsJson) {
  ScratchFolder folder;
  std::vector<NamedMaterial> materials;
  for (const std::string& name : kAwkwardNames) materials.emplace_back(name, Material{});
  materials.emplace_back(" padded ", Material{});  // JSON holds what MTL cannot
  save_materials_json(folder.file("m.json"), materials);
  const std::vector<NamedMaterial> back = load_materials_json(folder.file("m.json"));
  ASSERT_EQ(back.size(), materials.size());
  for (std::size_t i = 0; i < back.size(); ++i) EXPECT_EQ(back[i].first, materials[i].first);
}

Scene scene_with_awkward_names() {
  Scene scene;
  for (const std::string& name : kAwkwardNames) {
    scene.material_names.push_back(name);
    scene.materials.push_back(Material{});
    Object sphere;
    sphere.type = ObjectType::sphere;
    sphere.name = name + " object";
    sphere.radius = 1.0f;
    sphere.material = static_cast<int>(scene.materials.size()) - 1;
    scene.objects.push_back(sphere);
  }
  return scene;
}

TEST(NameBytes, SceneJsonWriterAndReaderKeepEveryNameByteForByte) {
  const Scene scene = scene_with_awkward_names();
  const std::string text = scene_to_json_text(scene);
  const Scene back = parse_scene(text, "names.json");
  ASSERT_EQ(back.objects.size(), scene.objects.size());
  for (std::size_t i = 0; i < back.objects.size(); ++i) {
    EXPECT_EQ(back.objects[i].name, scene.objects[i].name);
    EXPECT_EQ(back.material_names[back.objects[i].material],
              scene.material_names[scene.objects[i].material]);
  }
  EXPECT_EQ(scene_to_json_text(back), text);  // load -> save -> load -> save: a fixed point
}

TEST(NameBytes, RecoveryFileKeepsNamesAndTheScenePath) {
  Scene scene = scene_with_awkward_names();
  scene.path = "/tmp/sc\xE8ne.json";
  const Recovery back = parse_recovery(recovery_text(scene, 2), "recovery.json");
  EXPECT_EQ(back.scene.path, scene.path);
  EXPECT_EQ(back.scene.objects[0].name, "Terrain\xE6k object");
}

TEST(NameBytes, SceneEmbeddedInAPngReadsBack) {
  ScratchFolder folder;
  const Scene scene = scene_with_awkward_names();
  Image image(2, 1);
  write_png(folder.file("x.png"), image, false, {{"gloss:scene", scene_to_json_text(scene)}});
  const Png8 png = read_png(folder.file("x.png"));
  ASSERT_EQ(png.text.size(), 1u);
  EXPECT_EQ(parse_scene(png.text[0].second, "x.png").objects[0].name, "Terrain\xE6k object");
}

// An OBJ whose MTL names its material in Latin-1: the scene loads (the loader adds the material
// "STEM/NAME"), saves and loads again with the same bytes.
TEST(NameBytes, MeshMaterialFromAnMtlSurvivesSaveAndLoad) {
  ScratchFolder folder;
  std::ofstream(folder.file("t.mtl"), std::ios::binary) << "newmtl Terrain\xE6k\nKd 0.5 0.5 0.5\n";
  std::ofstream(folder.file("t.obj"), std::ios::binary)
      << "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl Terrain\xE6k\nf 1 2 3\n";
  std::ofstream(folder.file("s.json"), std::ios::binary)
      << R"({"objects": [{"type": "mesh", "name": "m", "file": "t.obj"}]})";
  const Scene scene = load_scene(folder.file("s.json"));
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.material_names[scene.objects[0].material], "t/Terrain\xE6k");
  save_scene(scene, folder.file("saved.json"));
  const Scene back = load_scene(folder.file("saved.json"));
  ASSERT_EQ(back.objects.size(), 1u);
  EXPECT_EQ(back.material_names[back.objects[0].material], "t/Terrain\xE6k");
  EXPECT_EQ(back.objects[0].params.group, "Terrain\xE6k");
}

}  // namespace
}  // namespace gloss

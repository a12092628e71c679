// Reopening a PNG as its scene (io/image/scene_in_png.h): the round trip, the one-line refusal of a
// PNG without a scene, errors inside the embedded JSON naming the PNG and the place, model paths,
// and the hint for a materials file opened as a scene.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "base/error.h"
#include "io/image/image_io.h"
#include "io/image/scene_in_png.h"
#include "io/scene/scene_loader.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

const char* const kTinyScene = R"({
  "camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y": 40},
  "lights": [{"position": [2, 3, 4]}],
  "materials": {"m": {"preset": "gold", "shininess": 17.25}},
  "objects": [{"type": "sphere", "center": [0.125, 0, 0], "radius": 1, "material": "m"}],
  "render": {"width": 8, "height": 6, "model": "blinn-phong"}
})";

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A 2x1 PNG carrying the given text chunks.
void write_tiny_png(const std::string& path, const TextChunks& text) {
  Image image(2, 1);
  image.at(0, 0) = glm::vec3(0.5f);
  write_png(path, image, false, text);
}

// The message of the InputError that loading path throws ("" when nothing is thrown).
std::string load_error(const std::string& path) {
  try {
    load_scene(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneInPng, EmbeddedSceneLoadsBackEqualAndUntitled) {
  ScratchFolder folder;
  const Scene scene = parse_scene(kTinyScene, folder.file("tiny.json"));
  write_tiny_png(folder.file("shot.png"),
                 {{"Software", "gloss"}, {kSceneChunkKeyword, embedded_scene_text(scene)}});
  const Scene back = load_scene(folder.file("shot.png"));
  EXPECT_EQ(scene_to_json_text(back), scene_to_json_text(scene));
  EXPECT_EQ(back.render.model, ShadingModel::blinn_phong);
  EXPECT_EQ(back.materials.at(0).shininess, 17.25f);
  EXPECT_EQ(back.objects.at(0).center.x, 0.125f);
  // Untitled: saving must ask for a name instead of writing JSON over the PNG.
  EXPECT_EQ(back.path, "");
}

TEST(SceneInPng, PngWithoutSceneIsRefusedInOneLine) {
  ScratchFolder folder;
  const std::string path = folder.file("plain.png");
  write_tiny_png(path, {{"Software", "some other program"}});
  EXPECT_EQ(load_error(path), path +
                                  ": this PNG carries no scene (no 'gloss:scene' text); only PNGs "
                                  "written by gloss or gloss-cli reopen as scenes");
}

TEST(SceneInPng, ErrorsInsideTheEmbeddedSceneNameThePngAndThePlace) {
  ScratchFolder folder;
  const std::string bad_value = folder.file("bad-value.png");
  std::string text = kTinyScene;
  text.replace(text.find("\"radius\": 1"), 11, "\"radius\": -1");
  write_tiny_png(bad_value, {{kSceneChunkKeyword, text}});
  const std::string value_error = load_error(bad_value);
  EXPECT_EQ(value_error.rfind(bad_value + " (embedded scene): objects[0].radius: ", 0), 0u)
      << value_error;

  // Line 2 is `  "camera": {"eye": [0, 0, 4] "target"...` with the comma after the eye array
  // removed: the parser stops on the string "target", whose closing quote is column 38.
  const std::string bad_syntax = folder.file("bad-syntax.png");
  text = kTinyScene;
  text.erase(text.find("], \"target\"") + 1, 1);
  write_tiny_png(bad_syntax, {{kSceneChunkKeyword, text}});
  const std::string syntax_error = load_error(bad_syntax);
  EXPECT_EQ(syntax_error.rfind(bad_syntax + " (embedded scene):2:38: ", 0), 0u) << syntax_error;
}

TEST(SceneInPng, ModelPathsAreEmbeddedAbsoluteSoThePngOpensFromAnotherFolder) {
  ScratchFolder scene_folder, png_folder;
  const std::string obj = std::string(GLOSS_TEST_DATA_DIR) + "/obj/cube.obj";
  std::filesystem::copy_file(obj, scene_folder.file("cube.obj"));
  std::filesystem::copy_file(std::string(GLOSS_TEST_DATA_DIR) + "/obj/cube.mtl",
                             scene_folder.file("cube.mtl"));
  write_text(scene_folder.file("scene.json"),
             R"({"objects": [{"type": "mesh", "file": "cube.obj"}]})");
  const Scene scene = load_scene(scene_folder.file("scene.json"));
  write_tiny_png(png_folder.file("shot.png"), {{kSceneChunkKeyword, embedded_scene_text(scene)}});
  const Scene back = load_scene(png_folder.file("shot.png"));
  ASSERT_EQ(back.objects.size(), scene.objects.size());
  EXPECT_EQ(back.objects[0].params.file,
            std::filesystem::absolute(scene_folder.file("cube.obj")).lexically_normal().string());
  ASSERT_TRUE(back.objects[0].mesh);
  EXPECT_EQ(back.objects[0].mesh->triangles.size(), scene.objects[0].mesh->triangles.size());
}

TEST(SceneInPng, OnlyTheSignatureMakesAPng) {
  ScratchFolder folder;
  write_text(folder.file("fake.png"), "{}");
  EXPECT_FALSE(has_png_signature(folder.file("fake.png")));
  EXPECT_FALSE(has_png_signature(folder.file("missing.png")));
  write_tiny_png(folder.file("real.json"), {});
  EXPECT_TRUE(has_png_signature(folder.file("real.json")));
}

TEST(SceneInPng, AMaterialsFileOpenedAsASceneSaysToLoadItAsMaterials) {
  const std::string json = std::string(GLOSS_TEST_DATA_DIR) + "/materials/library.json";
  EXPECT_EQ(load_error(json), json +
                                  ": this is a materials file, not a scene: load it with File > "
                                  "Load materials in the editor");
  const std::string mtl = std::string(GLOSS_TEST_DATA_DIR) + "/obj/cube.mtl";
  EXPECT_EQ(load_error(mtl), mtl +
                                 ": this MTL file is a materials file, not a scene: load it with "
                                 "File > Load materials in the editor");
}

}  // namespace
}  // namespace gloss

// The real gloss-cli executable (GLOSS_CLI_PATH) against docs/spec/scene-and-cli.md: outputs, exit
// status 0 / 2 / 1, one "error:" line naming the file, and no output left behind by a failure.
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/image/image_io.h"
#include "io/material/preset_table.h"
#include "io/scene/scene_loader.h"
#include "support/cli_run.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

// A small scene that renders in milliseconds.
const char* const kTinyScene = R"({
  "camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y": 40},
  "lights": [{"position": [2, 3, 4]}],
  "materials": {"m": {"preset": "gold"}},
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}],
  "render": {"width": 40, "height": 30}
})";

class Cli : public ::testing::Test {
 protected:
  void SetUp() override { write("tiny.json", kTinyScene); }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(inputs.file(name), std::ios::binary) << text;
  }
  CliRun run(const std::string& args) { return run_cli(args, logs, outputs.path().string()); }
  // A failure: the status, one stderr line "error: ..." naming what, nothing in outputs.
  void expect_failure(const CliRun& r, int status, const std::string& names) {
    EXPECT_EQ(r.status, status) << r.err;
    const std::vector<std::string> lines = lines_of(r.err);
    ASSERT_EQ(lines.size(), 1u) << r.err;
    EXPECT_EQ(lines[0].rfind("error: ", 0), 0u) << lines[0];
    EXPECT_NE(lines[0].find(names), std::string::npos) << lines[0];
    EXPECT_TRUE(outputs.entries().empty()) << outputs.entries().front();
  }
  std::string scene(const std::string& name = "tiny.json") { return "'" + inputs.file(name) + "'"; }

  ScratchFolder inputs, outputs, logs;
};

TEST_F(Cli, RenderWritesPngAndPfmAtTheRequestedSize) {
  const CliRun r =
      run("render " + scene() + " -o out.png --pfm out.pfm --width 24 --height 12 --spp 2");
  ASSERT_EQ(r.status, 0) << r.err;
  const Png8 png = read_png(outputs.file("out.png"));
  EXPECT_EQ(png.width, 24);
  EXPECT_EQ(png.height, 12);
  const Image pfm = read_pfm(outputs.file("out.pfm"));
  EXPECT_EQ(pfm.width, 24);
  EXPECT_EQ(pfm.height, 12);
  EXPECT_NE(r.out.find("out.png"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" ms"), std::string::npos) << r.out;
}

TEST_F(Cli, PngCarriesSoftwareSceneAndSettingsChunks) {
  const CliRun r = run("render " + scene() + " -o out.png --model blinn-phong --shadows off");
  ASSERT_EQ(r.status, 0) << r.err;
  const Png8 png = read_png(outputs.file("out.png"));
  std::string software, scene_text, settings;
  for (const auto& [key, text] : png.text) {
    if (key == "Software") software = text;
    if (key == "gloss:scene") scene_text = text;
    if (key == "gloss:settings") settings = text;
  }
  EXPECT_EQ(software, "gloss 0.1.0");
  EXPECT_EQ(settings.rfind("40x30, 1 spp, blinn-phong, shadows off", 0), 0u) << settings;
  // The embedded scene is the one rendered, overrides included, and loads again.
  const Scene embedded = parse_scene(scene_text, inputs.file("tiny.json"));
  EXPECT_EQ(embedded.render.model, ShadingModel::blinn_phong);
  EXPECT_FALSE(embedded.render.shadows);
}

TEST_F(Cli, WithoutOutputOptionsWritesSceneStemPngInTheCurrentFolder) {
  const CliRun r = run("render " + scene());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(outputs.entries(), std::vector<std::string>{"tiny.png"});
  EXPECT_EQ(read_png(outputs.file("tiny.png")).width, 40);
}

TEST_F(Cli, TermsWritesFivePfmAndFivePngIntoANewFolder) {
  const CliRun r = run("render " + scene() + " --terms terms/run1");
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(outputs.path() / "terms/run1")) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  const std::vector<std::string> expected = {
      "ambient.pfm",  "ambient.png",  "diffuse.pfm",  "diffuse.png", "emissive.pfm",
      "emissive.png", "specular.pfm", "specular.png", "total.pfm",   "total.png"};
  EXPECT_EQ(names, expected);
}

TEST_F(Cli, PresetsPrintsAHeaderAnd24Rows) {
  const CliRun r = run("presets");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<std::string> lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 25u) << r.out;
  EXPECT_EQ(lines[0].rfind("name", 0), 0u);
  EXPECT_EQ(lines[1].rfind("emerald ", 0), 0u) << lines[1];
  // gold: kd 0.75164 0.60648 0.22648 to 3 decimals, shininess 0.4, exponent 0.4 x 128 = 51.2.
  bool gold_seen = false;
  for (const std::string& line : lines) {
    if (line.rfind("gold ", 0) != 0) continue;
    gold_seen = true;
    EXPECT_NE(line.find("0.752 0.606 0.226"), std::string::npos) << line;
    EXPECT_NE(line.find("51.2"), std::string::npos) << line;
  }
  EXPECT_TRUE(gold_seen);
  EXPECT_EQ(lines[24].rfind("yellow_rubber ", 0), 0u) << lines[24];
}

TEST_F(Cli, VersionAndHelpExitZero) {
  const CliRun version = run("--version");
  EXPECT_EQ(version.status, 0);
  EXPECT_EQ(version.out, "gloss-cli 0.1.0\n");
  const CliRun help = run("render --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("--terms"), std::string::npos);
}

TEST_F(Cli, MissingSceneFileExitsTwo) {
  expect_failure(run("render " + scene("absent.json")), 2, "absent.json");
}

TEST_F(Cli, SceneThatIsNotJsonExitsTwoWithLineAndColumn) {
  write("prose.json", "\n\nnot json\n");
  expect_failure(run("render " + scene("prose.json") + " -o out.png"), 2, "prose.json:3:2:");
}

TEST_F(Cli, TruncatedSceneExitsTwoWithLineAndColumn) {
  // Cut after the second line: the end of the text is line 3, column 1.
  write("cut.json", "{\n  \"objects\": [\n");
  expect_failure(run("render " + scene("cut.json") + " -o out.png"), 2, "cut.json:3:1:");
}

TEST_F(Cli, UnknownOptionExitsTwo) {
  expect_failure(run("render " + scene() + " -o out.png --glossy"), 2, "--glossy");
  expect_failure(run("render " + scene() + " -o out.png --glossy"), 2, "tiny.json");
}

TEST_F(Cli, AnUnknownCommandIsNamedWithTheNearestOne) {
  expect_failure(run("rendr " + scene()), 2,
                 "error: unknown command 'rendr' (did you mean 'render'?)");
  const CliRun far = run("frobnicate");
  EXPECT_EQ(far.status, 2);
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
}

TEST_F(Cli, ImpossibleOverridesExitTwoNamingTheOption) {
  expect_failure(run("render " + scene() + " -o out.png --width 0"), 2, "tiny.json: --width:");
  expect_failure(run("render " + scene() + " -o out.png --height 99999"), 2, "--height");
  expect_failure(run("render " + scene() + " -o out.png --spp 0"), 2, "tiny.json: --spp:");
  expect_failure(run("render " + scene() + " -o out.png --model phongg"), 2,
                 "tiny.json: --model: unknown shading model 'phongg' (did you mean 'phong'?)");
  expect_failure(run("render " + scene() + " -o out.png --shadows maybe"), 2, "--shadows");
}

TEST_F(Cli, InvalidSceneContentExitsTwoNamingTheField) {
  write("key.json", R"({"objects": [], "rendr": {}})");
  expect_failure(run("render " + scene("key.json")), 2, "key.json: rendr: unknown key 'rendr'");
  write("preset.json", R"({"materials": {"m": {"preset": "goldd"}}, "objects": []})");
  expect_failure(run("render " + scene("preset.json")), 2,
                 "preset.json: materials.m.preset: unknown preset 'goldd'");
  write("model.json", R"({"objects": [], "render": {"model": "gouraud"}})");
  expect_failure(run("render " + scene("model.json")), 2, "model.json: render.model:");
}

// PNG bytes in a file named .jpg: refused, exit 2, nothing written (new-user review).
TEST_F(Cli, AnOutputNamedForAnotherFormatExitsTwo) {
  expect_failure(run("render " + scene() + " -o shot.jpg"), 2,
                 "shot.jpg: -o writes PNG: name the file *.png");
  expect_failure(run("render " + scene() + " --pfm out.png"), 2, "out.png: --pfm writes PFM");
  expect_failure(run("render " + scene() + " --exr out.hdr"), 2, "out.hdr: --exr writes OpenEXR");
  EXPECT_FALSE(std::filesystem::exists(outputs.path() / "shot.jpg"));
  EXPECT_EQ(run("render " + scene() + " -o SHOT.PNG --width 8 --height 6").status, 0);
}

TEST_F(Cli, OutputInAMissingFolderExitsOne) {
  expect_failure(run("render " + scene() + " -o no/such/folder/out.png"), 1, "no/such/folder");
  expect_failure(run("render " + scene() + " -o out.png --pfm no/such/out.pfm"), 1, "no/such");
}

TEST_F(Cli, OutputInAReadOnlyFolderExitsOneAndLeavesNothing) {
  std::string target;
  if (::geteuid() == 0) {
    target = "/proc/gloss-cli-test-out.pfm";  // root may write anywhere except such file systems
  } else {
    std::filesystem::create_directories(outputs.path() / "locked");
    ::chmod((outputs.path() / "locked").c_str(), 0555);
    target = "locked/out.pfm";
  }
  const CliRun r = run("render " + scene() + " -o out.png --pfm " + target);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  EXPECT_EQ(lines_of(r.err).size(), 1u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(outputs.file("out.png")));
  if (::geteuid() == 0) {
    EXPECT_FALSE(std::filesystem::exists(target));
  } else {
    EXPECT_TRUE(std::filesystem::is_empty(outputs.path() / "locked"));
    ::chmod((outputs.path() / "locked").c_str(), 0755);
  }
}

// A PNG that gloss-cli wrote carries its scene (docs/spec/scene-and-cli.md, "Reopening a PNG"):
// rendered again it gives the same pixels, overrides included; a relative OBJ path still resolves
// with the PNG in another folder.
TEST_F(Cli, RenderingAPngItWroteGivesIdenticalPixels) {
  const std::string obj_dir = std::string(GLOSS_TEST_DATA_DIR) + "/obj/";
  std::filesystem::copy_file(obj_dir + "cube.obj", inputs.file("cube.obj"));
  std::filesystem::copy_file(obj_dir + "cube.mtl", inputs.file("cube.mtl"));
  write("mesh.json", R"({
    "camera": {"eye": [2, 2, 4], "target": [0, 0, 0], "fov_y": 40},
    "lights": [{"position": [2, 3, 4]}],
    "materials": {"m": {"preset": "silver"}},
    "objects": [{"type": "sphere", "center": [1, 0, 0], "radius": 0.5, "material": "m"},
                {"type": "mesh", "file": "cube.obj", "scale": 0.5}]})");
  for (const char* name : {"tiny.json", "mesh.json"}) {
    SCOPED_TRACE(name);
    const CliRun first =
        run("render " + scene(name) + " -o first.png --width 32 --height 20 --spp 3 --model " +
            "blinn-phong --shadows off");
    ASSERT_EQ(first.status, 0) << first.err;
    const CliRun again = run("render first.png -o again.png");
    ASSERT_EQ(again.status, 0) << again.err;
    const Png8 a = read_png(outputs.file("first.png"));
    const Png8 b = read_png(outputs.file("again.png"));
    EXPECT_EQ(b.width, 32);
    EXPECT_EQ(b.height, 20);
    EXPECT_TRUE(a.rgb == b.rgb);
    std::filesystem::remove(outputs.file("first.png"));
    std::filesystem::remove(outputs.file("again.png"));
  }
}

TEST_F(Cli, APngSceneWithoutOutputOptionsIsNotOverwritten) {
  ASSERT_EQ(run("render " + scene() + " -o shot.png").status, 0);
  const CliRun r = run("render shot.png");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(outputs.entries(), (std::vector<std::string>{"shot-rerender.png", "shot.png"}));
}

TEST_F(Cli, APngWithoutASceneExitsTwoSayingSo) {
  Image image(4, 2);
  write_png(inputs.file("plain.png"), image, false, {{"Software", "another program"}});
  expect_failure(run("render " + scene("plain.png") + " -o out.png"), 2,
                 "plain.png: this PNG carries no scene (no 'gloss:scene' text); only PNGs "
                 "written by gloss or gloss-cli reopen as scenes");
}

// A scene naming a glTF model: render prints the model's import notes on stderr as the editor's
// Add model lists them (each glTF material as the fitted Phong or by assimp's rule), prefixed
// with the scene file and the object's field, and still exits 0. The model: one triangle, its
// positions (0,0,0) (1,0,0) (0,1,0) in a data: URI, material "red" (base colour (0.8, 0.1, 0.1),
// metallic 0, roughness 0.5).
TEST_F(Cli, RenderPrintsTheGltfModelsImportNotes) {
  write("tri.gltf", R"({
    "asset": {"version": "2.0"},
    "buffers": [{"byteLength": 36,
                 "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [0, 0, 0], "max": [1, 1, 0]}],
    "materials": [{"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.1, 1],
                   "metallicFactor": 0, "roughnessFactor": 0.5}}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
    "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})");
  std::string text = kTinyScene;
  const std::string sphere = R"("radius": 1, "material": "m"})";
  text.replace(text.find(sphere), sphere.size(),
               std::string(sphere) + R"(, {"type": "mesh", "file": "tri.gltf"})");
  write("with-model.json", text);
  const CliRun r = run("render " + scene("with-model.json") + " -o out.png");
  EXPECT_EQ(r.status, 0) << r.err;
  const std::string note = "note: " + inputs.file("with-model.json") +
                           ": objects[1].file: material 'red': metallic-roughness ";
  const std::vector<std::string> lines = lines_of(r.err);
  EXPECT_TRUE(std::any_of(lines.begin(), lines.end(), [&](const std::string& line) {
    return line.rfind(note, 0) == 0;
  })) << r.err;
}

TEST_F(Cli, AMaterialsFileAsTheSceneSaysToLoadItAsMaterials) {
  write("library.json", R"({"materials": {"red": {"diffuse": [0.6, 0.1, 0.1]}}})");
  expect_failure(run("render " + scene("library.json") + " -o out.png"), 2,
                 "library.json: this is a materials file, not a scene: load it with File > Load "
                 "materials in the editor");
}

}  // namespace
}  // namespace gloss

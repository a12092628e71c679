// gloss-cli keeps the contract on users' own content (docs/spec/scene-and-cli.md): names that
// are not UTF-8 render and embed, impossible numbers and scenes too big for memory exit 2 with
// one line naming the field, control characters are escaped, a full disk says so.
#include <sys/mount.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "io/image/image_io.h"
#include "io/scene/scene_loader.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

struct CliResult {
  int status = -1;
  std::string err;
};

// cd outputs && gloss-cli args, stderr captured in logs.
CliResult run_cli(const std::string& args, const ScratchFolder& outputs,
                  const ScratchFolder& logs) {
  const std::string err = logs.file("stderr.txt");
  const std::string command = "cd '" + outputs.path().string() + "' && '" + GLOSS_CLI_PATH + "' " +
                              args + " >/dev/null 2>'" + err + "'";
  const int raw = std::system(command.c_str());
  CliResult run;
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream in(err, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  run.err = text.str();
  return run;
}

class CliContract : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(inputs.file(name), std::ios::binary) << text;
    return "'" + inputs.file(name) + "'";
  }
  CliResult run(const std::string& args) { return run_cli(args, outputs, logs); }
  // Exit 2 (or status), one line "error: FILE: FIELD: ..." containing fragment, no output.
  void expect_error(const CliResult& r, int status, const std::string& fragment) {
    EXPECT_EQ(r.status, status) << r.err;
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
    EXPECT_TRUE(outputs.entries().empty());
  }
  ScratchFolder inputs, outputs, logs;
};

const char* const kHead = R"({"camera": {"eye": [0, 0, 4], "target": [0, 0, 0]},
  "lights": [{"position": [2, 3, 4]}], "render": {"width": 8, "height": 6}, )";

TEST_F(CliContract, AnMtlNameThatIsNotUtf8RendersAndIsEmbeddedLosslessly) {
  write("t.mtl", "newmtl Terrain\xE6k\nKd 0.5 0.5 0.5\n");
  write("t.obj", "mtllib t.mtl\nv -1 -1 0\nv 1 -1 0\nv 0 1 0\nusemtl Terrain\xE6k\nf 1 2 3\n");
  const std::string scene =
      write("s.json",
            std::string(kHead) + R"("objects": [{"type": "mesh", "name": "m", "file": "t.obj"}]})");
  const CliResult r = run("render " + scene + " -o out.png");
  ASSERT_EQ(r.status, 0) << r.err;
  const Png8 png = read_png(outputs.file("out.png"));
  std::string embedded;
  for (const auto& [key, text] : png.text) {
    if (key == "gloss:scene") embedded = text;
  }
  const Scene back = parse_scene(embedded, inputs.file("s.json"));
  EXPECT_EQ(back.material_names[back.objects.at(0).material], "t/Terrain\xE6k");
}

TEST_F(CliContract, ACameraBeyondFloatArithmeticExitsTwoNamingTheField) {
  const std::string scene =
      write("far.json", R"({"camera": {"eye": [0, 0, 1.85e19], "target": [0, 0, 0]},
                            "materials": {"m": {}},
                            "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                                         "material": "m"}]})");
  expect_error(run("render " + scene + " -o out.png"), 2, "far.json: camera.eye[2]: ");
}

TEST_F(CliContract, TooManyTeapotsExitTwoNamingTheObjectAndTheBudget) {
  std::string objects;
  for (int i = 0; i < 1000; ++i) {
    objects +=
        std::string(i ? ", " : "") + R"({"type": "teapot", "tessellation": 64, "material": "m"})";
  }
  const std::string scene = write("pots.json", std::string(kHead) + R"("materials": {"m": {}},
                                  "objects": [)" + objects +
                                                   "]}");
  ::setenv("GLOSS_MEMORY_BUDGET_MB", "100", 1);
  const CliResult r = run("render " + scene + " -o out.png");
  ::unsetenv("GLOSS_MEMORY_BUDGET_MB");
  // 50 MB per teapot at tessellation 64 (tests/io/test_memory_budget.cpp): the third passes.
  expect_error(r, 2,
               "pots.json: objects[2]: teapot, tessellation 64, 262144 triangles: the scene needs "
               "~150 MB with it, budget 100 MB (GLOSS_MEMORY_BUDGET_MB)");
}

TEST_F(CliContract, ControlCharactersInNamesReachTheTerminalEscaped) {
  const std::string scene = write("esc.json", std::string(kHead) + R"("materials": {"m": {}},
            "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                         "material": "red\u001b[2J\r"}]})");
  const CliResult r = run("render " + scene + " -o out.png");
  expect_error(r, 2, "unknown material 'red\\x1B[2J\\x0D'");
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos);
  EXPECT_EQ(r.err.find('\r'), std::string::npos);
}

// A 64 KiB tmpfs cannot take a 3 MB PFM (512 x 512 x 12 bytes). Needs mount rights (root); skipped
// without them.
TEST_F(CliContract, AFullDiskSaysDiskFullAndLeavesNothing) {
  const std::filesystem::path small = outputs.path() / "small";
  std::filesystem::create_directory(small);
  if (::mount("tmpfs", small.c_str(), "tmpfs", 0, "size=64k") != 0) {
    GTEST_SKIP() << "cannot mount a tmpfs here: " << std::strerror(errno);
  }
  const std::string scene = write("tiny.json", std::string(kHead) + R"("materials": {"m": {}},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})");
  const CliResult r = run("render " + scene + " --width 512 --height 512 --pfm small/out.pfm");
  const bool empty = std::filesystem::is_empty(small);
  ::umount(small.c_str());
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(r.err, "error: disk full writing small/out.pfm\n");
  EXPECT_TRUE(empty);
}

}  // namespace
}  // namespace gloss

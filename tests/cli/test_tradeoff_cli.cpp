// gloss-cli tradeoff end to end (GLOSS_CLI_PATH): the table, the CSV, the plot through Debian's
// /usr/bin/python3, exit status 2 for a bad scene and 1 for an unwritable output, nothing left
// behind by a failure.
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/image/image_io.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

struct TradeoffRun {
  int status = -1;
  std::string out, err;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A sphere over a floor quad, lit from above: shadows, a mesh for Gouraud, no teapot.
const char* const kScene = R"({
  "camera": {"eye": [0, 1.5, 4], "target": [0, 0.3, 0], "up": [0, 1, 0], "fov_y": 40},
  "lights": [{"position": [2, 4, 3]}],
  "materials": {"m": {"preset": "silver"}},
  "objects": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5, "material": "m"},
              {"type": "quad", "vertices": [[-3, 0, -3], [3, 0, -3], [3, 0, 3], [-3, 0, 3]],
               "material": "m"}],
  "render": {"width": 32, "height": 24}
})";

class TradeoffCli : public ::testing::Test {
 protected:
  void SetUp() override { std::ofstream(inputs.file("scene.json")) << kScene; }
  TradeoffRun run(const std::string& args) {
    const std::string out = logs.file("out.txt"), err = logs.file("err.txt");
    const std::string command = "cd '" + outputs.path().string() + "' && '" + GLOSS_CLI_PATH +
                                "' tradeoff " + args + " >'" + out + "' 2>'" + err + "'";
    const int raw = std::system(command.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
  }
  std::string scene() const { return "'" + inputs.file("scene.json") + "'"; }
  static constexpr const char* kSmall = " --width 24 --height 18 --runs 1 --reference-spp 4";
  ScratchFolder inputs, outputs, logs;
};

TEST_F(TradeoffCli, PrintsEveryKnobAndWritesTheCsv) {
  const TradeoffRun r = run(scene() + kSmall + " --csv rows.csv");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* knob : {"spp", "pow", "precision", "shading", "resolution", "shadows"}) {
    EXPECT_NE(r.out.find(std::string("\n  ") + knob + " "), std::string::npos) << knob;
  }
  EXPECT_NE(r.out.find("tessellation: skipped"), std::string::npos) << r.out;
  const std::string csv = slurp(outputs.file("rows.csv"));
  EXPECT_EQ(csv.rfind("knob,setting,time_ms,rmse,psnr_db,max_abs,pct_pixels_off\nspp,1,", 0), 0u)
      << csv;
  EXPECT_EQ(outputs.entries(), std::vector<std::string>{"rows.csv"});
}

TEST_F(TradeoffCli, PlotIsAPngWrittenAtomically) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "Debian's python3-matplotlib is not installed";
  }
  const TradeoffRun r = run(scene() + kSmall + " --plot plot.png");
  ASSERT_EQ(r.status, 0) << r.err;
  const Png8 png = read_png(outputs.file("plot.png"));
  EXPECT_GT(png.width, 300);
  EXPECT_GT(png.height, 200);
  EXPECT_EQ(outputs.entries(), std::vector<std::string>{"plot.png"});  // no temporary left
}

TEST_F(TradeoffCli, BadSceneExitsWith2NamingTheFile) {
  std::ofstream(inputs.file("bad.json")) << "{\"camera\": ";
  const TradeoffRun r = run("'" + inputs.file("bad.json") + "'" + kSmall + " --csv rows.csv");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("bad.json"), std::string::npos) << r.err;
  EXPECT_TRUE(outputs.entries().empty());
}

// The scene has no teapot: asked for the tessellation knob alone, nothing is measured. That is
// said (exit 2), not an empty table, nor the plot script's TypeError; a plot not named .png is
// refused before anything runs.
TEST_F(TradeoffCli, NothingMeasuredAndAPlotNamedForAnotherFormatExitTwo) {
  const TradeoffRun none = run(scene() + kSmall + " --knobs tessellation --csv rows.csv");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("nothing measured: no knob asked for applies to this scene"),
            std::string::npos)
      << none.err;
  const TradeoffRun jpg = run(scene() + kSmall + " --plot p.jpg");
  EXPECT_EQ(jpg.status, 2);
  EXPECT_NE(jpg.err.find("p.jpg: --plot writes PNG"), std::string::npos) << jpg.err;
  EXPECT_TRUE(outputs.entries().empty());
}

TEST_F(TradeoffCli, UnwritableOutputExitsWith1BeforeMeasuring) {
  for (const char* option : {" --csv no/such/folder/rows.csv", " --plot no/such/folder/p.png"}) {
    const TradeoffRun r = run(scene() + kSmall + option);
    EXPECT_EQ(r.status, 1) << option;
    EXPECT_EQ(r.err.rfind("error: cannot write no/such/folder/", 0), 0u) << r.err;
    EXPECT_EQ(r.out.find("spp "), std::string::npos) << "measured anyway: " << r.out;
    EXPECT_TRUE(outputs.entries().empty());
  }
}

}  // namespace
}  // namespace gloss

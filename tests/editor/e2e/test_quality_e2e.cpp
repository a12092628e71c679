// End-to-end: the Quality window's measurement driven by `quality` script lines in the real gloss
// under Xvfb (and without a display). The CSV header and knob names are the ones issue 5 and
// analysis/tradeoff/tradeoff.h specify; the knob list follows from the scene (tessellation needs a
// teapot).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "editor/e2e/editor_process.h"
#include "io/image/image_io.h"

namespace gloss {
namespace {

namespace fs = std::filesystem;

using test::EditorRun;
using test::read_text;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The knob of every data line of a tradeoff CSV.
std::set<std::string> knobs_in(const std::vector<std::string>& csv_lines) {
  std::set<std::string> knobs;
  for (std::size_t i = 1; i < csv_lines.size(); ++i) {
    knobs.insert(csv_lines[i].substr(0, csv_lines[i].find(',')));
  }
  return knobs;
}

class QualityE2E : public test::EditorProcessTest {
 protected:
  QualityE2E() : EditorProcessTest("gloss-quality-e2e-") {}
  // Runs gloss on scene (a path) with script_text; with_display = false runs it without X.
  EditorRun run(const std::string& scene, const std::string& script_text,
                bool with_display = true) {
    return run_editor(scene, script_text, with_display);
  }
};

const char* kHeader = "knob,setting,time_ms,rmse,psnr_db,max_abs,pct_pixels_off";

TEST_F(QualityE2E, MeasureWritesRowsForEveryKnobOfATeapotScene) {
  const EditorRun r =
      run(std::string(GLOSS_SCENES_DIR) + "/teapot.json",
          "quality measure\nscreenshot window.png window\nquality csv q.csv\nquit\n");
  if (r.status == -1) GTEST_SKIP() << "no xvfb-run";
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("quality: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("8 of 8 knobs"), std::string::npos) << r.out;
  const std::vector<std::string> csv = lines_of(read_text(m_dir / "q.csv"));
  ASSERT_GE(csv.size(), 2u);
  EXPECT_EQ(csv[0], kHeader);
  const std::set<std::string> expected{"spp",       "adaptive", "tessellation", "pow",
                                       "precision", "shading",  "resolution",   "shadows"};
  EXPECT_EQ(knobs_in(csv), expected);
  // The quick settings: spp 1, 2, 4, 8, 16; adaptive: the base and two thresholds;
  // tessellation 2..32; resolution 1/8..1; two each for the other four knobs.
  EXPECT_EQ(csv.size(), 1u + 5 + 3 + 5 + 2 + 2 + 2 + 4 + 2);
  const Png8 shot = read_png((m_dir / "window.png").string());
  EXPECT_EQ(shot.width, 1280);
}

TEST_F(QualityE2E, SpheresSceneSkipsTessellation) {
  const EditorRun r = run(std::string(GLOSS_APP_TEST_DATA) + "/gold_sphere.json",
                          "quality measure\nquality csv out/q.csv\nquit\n");
  if (r.status == -1) GTEST_SKIP() << "no xvfb-run";
  // out/ does not exist: the CSV write fails and names the line.
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("script.txt:2:"), std::string::npos) << r.err;
  fs::create_directories(m_dir / "out");
  const EditorRun again = run(std::string(GLOSS_APP_TEST_DATA) + "/gold_sphere.json",
                              "quality measure\nquality csv out/q.csv\nquit\n");
  ASSERT_EQ(again.status, 0) << again.err;
  const std::vector<std::string> csv = lines_of(read_text(m_dir / "out/q.csv"));
  ASSERT_GE(csv.size(), 2u);
  EXPECT_EQ(csv[0], kHeader);
  const std::set<std::string> expected{"spp",     "adaptive",   "pow",    "precision",
                                       "shading", "resolution", "shadows"};
  EXPECT_EQ(knobs_in(csv), expected);
}

TEST_F(QualityE2E, MeasureWorksWithoutADisplay) {
  const EditorRun r = run(std::string(GLOSS_APP_TEST_DATA) + "/gold_sphere.json",
                          "quality measure\nquality csv q.csv\n", false);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<std::string> csv = lines_of(read_text(m_dir / "q.csv"));
  ASSERT_GE(csv.size(), 2u);
  EXPECT_EQ(csv[0], kHeader);
  EXPECT_EQ(knobs_in(csv).size(), 7u);
}

TEST_F(QualityE2E, QuitWhileMeasuringEndsPromptly) {
  // A started measurement is cancelled and joined by the editor's exit; a hang would hit the
  // test's timeout, a crash a non-zero status.
  const EditorRun r = run(std::string(GLOSS_SCENES_DIR) + "/teapot.json", "quality start\nquit\n");
  if (r.status == -1) GTEST_SKIP() << "no xvfb-run";
  EXPECT_EQ(r.status, 0) << r.err;
}

}  // namespace
}  // namespace gloss

// End-to-end: the real gloss under Xvfb, driven by --script, checked through the PNG files it
// writes. Expected directions come from the preset table (gold's diffuse is (0.75, 0.61, 0.23),
// silver's (0.51, 0.51, 0.51)) and from docs/spec/shading.md (total = emissive + ambient +
// diffuse + specular), never from earlier output of the program.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "editor/e2e/editor_process.h"
#include "io/image/image_io.h"

namespace gloss {
namespace {

namespace fs = std::filesystem;

using test::EditorRun;
using test::read_text;

class EditorE2E : public test::EditorProcessTest {
 protected:
  EditorE2E() : EditorProcessTest("gloss-e2e-") {}
  // Runs gloss on the test scene with script_text; with_display = false runs it without X.
  EditorRun run(const std::string& script_text, bool with_display = true,
                const std::string& options = "") {
    return run_editor(std::string(GLOSS_APP_TEST_DATA) + "/gold_sphere.json", script_text,
                      with_display, options);
  }
};

// Mean of each channel over the pixels that are not background (the scene's background is black).
glm::dvec3 mean_of_lit(const Png8& png) {
  glm::dvec3 sum(0.0);
  long count = 0;
  for (std::size_t i = 0; i + 2 < png.rgb.size(); i += 3) {
    if (png.rgb[i] + png.rgb[i + 1] + png.rgb[i + 2] == 0) continue;
    sum += glm::dvec3(png.rgb[i], png.rgb[i + 1], png.rgb[i + 2]);
    ++count;
  }
  return count > 0 ? sum / static_cast<double>(count) : sum;
}

TEST_F(EditorE2E, GoldAndSilverDifferInTheExpectedDirection) {
  const EditorRun r =
      run("preset 0 gold\nwait\nscreenshot gold.png viewport\n"
          "preset 0 silver\nwait\nscreenshot silver.png viewport\nquit\n");
  if (r.status == -1) GTEST_SKIP() << "no xvfb-run";
  ASSERT_EQ(r.status, 0) << r.err;
  const glm::dvec3 gold = mean_of_lit(read_png((m_dir / "gold.png").string()));
  const glm::dvec3 silver = mean_of_lit(read_png((m_dir / "silver.png").string()));
  // Gold reflects red far more than blue; silver is neutral grey.
  EXPECT_GT(gold.x - gold.z, 40.0);
  EXPECT_NEAR(silver.x, silver.z, 2.0);
  EXPECT_GT(gold.x, silver.x);
  EXPECT_LT(gold.z, silver.z);
}

TEST_F(EditorE2E, TermSheetHasFourNonEmptyPanesThatSumToTheTotal) {
  const EditorRun r = run("view terms\nwait\nscreenshot sheet.png terms\nquit\n");
  if (r.status == -1) GTEST_SKIP() << "no xvfb-run";
  ASSERT_EQ(r.status, 0) << r.err;
  const Png8 sheet = read_png((m_dir / "sheet.png").string());
  ASSERT_EQ(sheet.width, 2 * 160);
  // Each pane sits under a strip with its name (export_image.h): 16 rows at this size.
  const int band = 16;
  ASSERT_EQ(sheet.height, 2 * (120 + band));
  const int w = 160, h = 120;
  auto at = [&](int pane, int x, int y, int c) {
    const int px = (pane % 2) * w + x, py = (pane / 2) * (h + band) + band + y;
    return static_cast<int>(sheet.rgb[(static_cast<std::size_t>(py) * sheet.width + px) * 3 + c]);
  };
  int lit[4] = {0, 0, 0, 0};
  int compared = 0, worst = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int pane = 0; pane < 4; ++pane) {
        if (at(pane, x, y, 0) + at(pane, x, y, 1) + at(pane, x, y, 2) > 0) ++lit[pane];
      }
      for (int c = 0; c < 3; ++c) {
        if (at(3, x, y, c) >= 250) continue;  // the total clamps at 255; its parts may not
        const int sum = at(0, x, y, c) + at(1, x, y, c) + at(2, x, y, c);
        worst = std::max(worst, std::abs(sum - at(3, x, y, c)));
        ++compared;
      }
    }
  }
  for (int pane = 0; pane < 4; ++pane) EXPECT_GT(lit[pane], 0) << "pane " << pane << " is empty";
  EXPECT_GT(compared, w * h);
  // Three parts rounded to 8 bits separately: at most 1.5 steps from the rounded total.
  EXPECT_LE(worst, 2);
}

TEST_F(EditorE2E, UndoRestoresTheEarlierImageExactly) {
  const EditorRun r =
      run("wait\nscreenshot before.png viewport\n"
          "set 0 diffuse 0.9 0.1 0.1\nset 0 shininess 5\nwait\nscreenshot edited.png viewport\n"
          "undo\nundo\nwait\nscreenshot after.png viewport\nquit\n");
  if (r.status == -1) GTEST_SKIP() << "no xvfb-run";
  ASSERT_EQ(r.status, 0) << r.err;
  const Png8 before = read_png((m_dir / "before.png").string());
  const Png8 edited = read_png((m_dir / "edited.png").string());
  const Png8 after = read_png((m_dir / "after.png").string());
  EXPECT_NE(before.rgb, edited.rgb);
  EXPECT_EQ(before.rgb, after.rgb);
}

TEST_F(EditorE2E, WindowScreenshotShowsTheWholeWindow) {
  const EditorRun r = run("view terms\nwait\nscreenshot window.png window\nstats\nquit\n");
  if (r.status == -1) GTEST_SKIP() << "no xvfb-run";
  ASSERT_EQ(r.status, 0) << r.err;
  const Png8 png = read_png((m_dir / "window.png").string());
  EXPECT_EQ(png.width, 1280);
  EXPECT_EQ(png.height, 800);
  int distinct = 0;
  for (std::size_t i = 3; i < png.rgb.size(); i += 3) distinct += png.rgb[i] != png.rgb[0];
  EXPECT_GT(distinct, 1000);
  EXPECT_NE(r.out.find("stats: ui_frame_ms"), std::string::npos) << r.out;
}

TEST_F(EditorE2E, ABadScriptLineIsAnErrorNamingTheLine) {
  const EditorRun r = run("wait\n# fine\nfrobnicate 2\nquit\n", false);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("script.txt:3:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("frobnicate"), std::string::npos) << r.err;
}

// A bad command-line option is one error line, exit 2, as every other bad input (it was CLI11's
// two lines without "error:").
TEST_F(EditorE2E, ABadOptionIsOneErrorLine) {
  const EditorRun r = run("quit\n", false, "--bogus");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("--bogus"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST_F(EditorE2E, ACommandThatFailsAtRunTimeNamesItsLine) {
  const EditorRun r = run("wait\npreset 3 gold\nquit\n");
  if (r.status == -1) GTEST_SKIP() << "no xvfb-run";
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("script.txt:2:"), std::string::npos) << r.err;
}

TEST_F(EditorE2E, WithoutADisplayTheScriptRunsOnTheCoreRenderer) {
  const EditorRun r = run("set 0 shininess 10\nscreenshot shot.png viewport\nquit\n", false);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("no display"), std::string::npos) << r.err;
  EXPECT_EQ(read_png((m_dir / "shot.png").string()).width, 160);
}

TEST_F(EditorE2E, WithoutADisplayGlossRendersTheSceneToAPng) {
  const std::string scene = std::string(GLOSS_APP_TEST_DATA) + "/gold_sphere.json";
  const std::string command = "cd '" + m_dir.string() + "' && env -u DISPLAY -u WAYLAND_DISPLAY " +
                              GLOSS_EDITOR_PATH + " '" + scene + "' > out.txt 2> err.txt";
  const int raw = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 0);
  EXPECT_NE(read_text(m_dir / "err.txt").find("no display"), std::string::npos);
  const std::string out = read_text(m_dir / "out.txt");
  const std::size_t at = out.find(" to ");
  ASSERT_NE(at, std::string::npos) << out;
  const std::string path = out.substr(at + 4, out.find('\n', at) - at - 4);
  EXPECT_TRUE(fs::exists(path)) << path;
  EXPECT_EQ(read_png(path).width, 160);
}

}  // namespace
}  // namespace gloss

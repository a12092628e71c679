// Converged means exact, end to end: the real gloss under Xvfb replays edits of every kind (light
// moves, undo and redo, a preset, a colour, the term view, a camera orbit, renderer switches
// including an Automatic drag that pauses the ray tracer), waits, and writes the frame it shows
// (`screenshot PATH shown`); gloss-cli then renders the scene that frame's PNG carries, at the
// frame's size, and every pixel must agree to 1e-6 (docs/spec/shading.md: one renderer).
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "editor/e2e/editor_process.h"
#include "io/image/image_io.h"

namespace gloss {
namespace {

using test::EditorRun;

class ConvergedE2E : public test::EditorProcessTest {
 protected:
  ConvergedE2E() : EditorProcessTest("gloss-converged-e2e-") {}
};

// Pixels with some channel more than tolerance apart; -1 when the sizes differ.
long pixels_off(const Image& a, const Image& b, double tolerance, double& worst) {
  worst = 0;
  if (a.width != b.width || a.height != b.height) return -1;
  long off = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    double d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(double(a.pixels[i][c]) - b.pixels[i][c]));
    worst = std::max(worst, d);
    off += d > tolerance ? 1 : 0;
  }
  return off;
}

TEST_F(ConvergedE2E, TheConvergedFrameAfterAnyEditsIsTheCliRender) {
  // Edits a frame or more apart (sleep lets frames run: first images, follow-ups cancelled).
  // The camera and renderer switches come first and are waited for, so the last edits (the
  // light, the preset, the colour) start from a converged image whose refined pixels they move.
  const std::string script =
      "wait\n"
      "camera orbit 12 4\nsleep 0.05\n"
      "renderer gl\nlight 0 position -2 7 5\nsleep 0.05\n"
      "renderer auto\nwait\n"
      "mouse press 0.5 0.5\nmouse move 0.53 0.51\nmouse move 0.56 0.52\nmouse release\n"
      "sleep 0.1\n"
      "renderer cpu\n"
      "view terms\nsleep 0.05\nview render\n"
      "wait\n"
      "light 0 position 3 6 4\nsleep 0.05\n"
      "light 0 position -4 6 3\nsleep 0.03\n"
      "undo\nsleep 0.02\nredo\nsleep 0.05\n"
      "preset 1 copper\nsleep 0.02\n"
      "set 0 diffuse 0.8 0.2 0.1\n"
      "wait\n"
      "screenshot shown.pfm shown\nscreenshot shown.png shown\n"
      "screenshot window.png window\nquit\n";
  const EditorRun r =
      run_editor(std::string(GLOSS_APP_TEST_DATA) + "/spheres_floor.json", script, true);
  if (r.status == -1) GTEST_SKIP() << "no xvfb-run";
  ASSERT_EQ(r.status, 0) << r.err;
  const Image shown = read_pfm((m_dir / "shown.pfm").string());
  const Png8 png = read_png((m_dir / "shown.png").string());
  ASSERT_EQ(png.width, shown.width);
  ASSERT_EQ(png.height, shown.height);
  std::string settings;
  for (const auto& [keyword, text] : png.text)
    if (keyword == "gloss:settings") settings = text;
  EXPECT_NE(settings.find("shown_spp=16 converged=yes"), std::string::npos) << settings;
  EXPECT_NE(settings.find("renderer=cpu"), std::string::npos) << settings;

  // The CLI renders the scene the PNG carries, at the size it says (the frame's).
  const std::string cli = std::string("'") + GLOSS_CLI_PATH + "' render '" +
                          (m_dir / "shown.png").string() + "' --pfm '" +
                          (m_dir / "cli.pfm").string() + "' 2> '" +
                          (m_dir / "cli-err.txt").string() + "'";
  ASSERT_EQ(std::system(cli.c_str()), 0) << test::read_text(m_dir / "cli-err.txt");
  const Image exported = read_pfm((m_dir / "cli.pfm").string());
  double worst = 0;
  EXPECT_EQ(pixels_off(shown, exported, 1e-6, worst), 0)
      << shown.width << "x" << shown.height << ", largest difference " << worst;
}

}  // namespace
}  // namespace gloss

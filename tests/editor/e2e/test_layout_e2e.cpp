// End-to-end: the window's layout at a laptop's size, read back from the editor's own `layout`
// line (script.h): the viewport keeps at least half of a 1024 x 640 window, panels collapse to
// strips and the viewport maximises (script lines and keys), the term and A/B panes fill the
// viewport, and an off-view light's arrow is hit where it is drawn and drags the light.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "editor/e2e/editor_process.h"
#include "io/image/image_io.h"

namespace gloss {
namespace {

using test::EditorRun;

constexpr const char* kLaptop = "--window-width 1024 --window-height 640";

struct Rect {
  float x = 0, y = 0, w = 0, h = 0;
};

// The value of key=X,Y,WxH in the n-th line of out that starts with prefix.
Rect rect_of(const std::string& out, const std::string& prefix, const std::string& key, int n = 0) {
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(prefix, 0) != 0 || n-- > 0) continue;
    const std::size_t at = line.find(" " + key + "=");
    Rect r;
    if (at == std::string::npos) return r;
    std::sscanf(line.c_str() + at + key.size() + 2, "%f,%f,%fx%f", &r.x, &r.y, &r.w, &r.h);
    return r;
  }
  return {};
}

// The n-th "layout: light 0 ..." line's marker fractions and position.
struct Light {
  float fx = -1, fy = -1;
  int on_screen = -1, selected = -1;
  float x = 0, y = 0, z = 0;
};
Light light_of(const std::string& out, int n = 0) {
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("layout: light 0 ", 0) != 0 || n-- > 0) continue;
    Light l;
    std::sscanf(line.c_str(),
                "layout: light 0 marker=%f,%f on_screen=%d selected=%d position=%f %f %f", &l.fx,
                &l.fy, &l.on_screen, &l.selected, &l.x, &l.y, &l.z);
    return l;
  }
  return {};
}

class LayoutE2E : public test::EditorProcessTest {
 protected:
  LayoutE2E() : EditorProcessTest("gloss-layout-e2e-") {}
  EditorRun run(const std::string& script) {
    return run_editor(std::string(GLOSS_SCENES_DIR) + "/spheres.json", script, true, kLaptop);
  }
};

TEST_F(LayoutE2E, AtLaptopSizeTheViewportKeepsHalfTheWidthAndPanesFillIt) {
  const EditorRun r =
      run("wait\nlayout\nview terms\nwait\nlayout\nview ab\nwait\nlayout\n"
          "screenshot shot.png window\nquit\n");
  if (r.status == -1) GTEST_SKIP() << "no xvfb-run";
  ASSERT_EQ(r.status, 0) << r.err;
  const Rect viewport = rect_of(r.out, "layout: window=1024x640", "viewport");
  EXPECT_GE(viewport.w, 512.0f) << r.out;  // the issue saw 288 x 216 here
  EXPECT_GE(viewport.h, 580.0f) << r.out;
  // The term view: four panes that cover the viewport, no band left empty.
  float area = 0;
  for (int i = 0; i < 4; ++i) {
    const Rect p = rect_of(r.out, "layout: mode=terms", "pane" + std::to_string(i));
    area += p.w * p.h;
  }
  EXPECT_GE(area, 0.99f * viewport.w * viewport.h) << r.out;
  // A/B: three panes and the legend, beside them, cover it too.
  area = 0;
  for (int i = 0; i < 3; ++i) {
    const Rect p = rect_of(r.out, "layout: mode=ab", "pane" + std::to_string(i));
    area += p.w * p.h;
  }
  const Rect legend = rect_of(r.out, "layout: mode=ab", "legend");
  EXPECT_GT(legend.w, 0.0f) << r.out;
  EXPECT_GE(area + legend.w * legend.h, 0.99f * viewport.w * viewport.h) << r.out;
  const Png8 shot = read_png((m_dir / "shot.png").string());
  EXPECT_EQ(shot.width, 1024);
  EXPECT_EQ(shot.height, 640);
}

TEST_F(LayoutE2E, PanelsCollapseToStripsAndTheViewportMaximises) {
  const EditorRun r =
      run("layout collapse left\nlayout collapse right\nlayout\n"
          "layout expand left\nlayout expand right\nkey Ctrl+Space\nlayout\n"
          "key Ctrl+Space\nkey [\nlayout\nquit\n");
  if (r.status == -1) GTEST_SKIP() << "no xvfb-run";
  ASSERT_EQ(r.status, 0) << r.err;
  // Both collapsed: two 24-pixel strips, the viewport between them.
  const Rect collapsed = rect_of(r.out, "layout: window", "viewport", 0);
  EXPECT_EQ(collapsed.x, 24.0f) << r.out;
  EXPECT_EQ(collapsed.w, 1024.0f - 48.0f) << r.out;
  EXPECT_EQ(rect_of(r.out, "layout: window", "left_strip", 0).w, 24.0f);
  EXPECT_EQ(rect_of(r.out, "layout: window", "left", 0).w, 0.0f);
  // Expanded, then maximised by its key: the whole width.
  const Rect maximised = rect_of(r.out, "layout: window", "viewport", 1);
  EXPECT_EQ(maximised.x, 0.0f) << r.out;
  EXPECT_EQ(maximised.w, 1024.0f) << r.out;
  // Restored by the same key, then the Material panel collapsed by its key.
  const Rect left_strip = rect_of(r.out, "layout: window", "left_strip", 2);
  EXPECT_EQ(left_strip.w, 24.0f) << r.out;
  EXPECT_GT(rect_of(r.out, "layout: window", "lights", 2).w, 200.0f) << r.out;
  // Splitters several pixels wide on the borders of expanded panels.
  EXPECT_GE(rect_of(r.out, "layout: window", "right_split", 2).w, 6.0f) << r.out;
}

TEST_F(LayoutE2E, AKeyNoShortcutHasIsABadLine) {
  const EditorRun r = run("key Ctrl+Alt+F12\nquit\n");
  if (r.status == -1) GTEST_SKIP() << "no xvfb-run";
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("script.txt:1: no keyboard shortcut 'Ctrl+Alt+F12'"), std::string::npos)
      << r.err;
}

// The afternoon's bug: the spheres scene's light is above the view, drawn as an arrow below the
// pane's label, but clicks were tested at the arrow's unclamped edge position, and an off-view
// light could not be dragged at all. Pressed where `layout` says it is drawn, the arrow selects
// the light and a drag brings it down into view; the camera does not orbit.
TEST_F(LayoutE2E, AnOffViewLightsArrowIsHitWhereDrawnAndDragsTheLight) {
  const EditorRun first = run("layout\nquit\n");
  if (first.status == -1) GTEST_SKIP() << "no xvfb-run";
  ASSERT_EQ(first.status, 0) << first.err;
  const Light before = light_of(first.out);
  ASSERT_EQ(before.on_screen, 0) << first.out;
  ASSERT_GT(before.fy, 0.0f) << first.out;
  char script[512];
  std::snprintf(script, sizeof script,
                "mouse press %.4f %.4f\nmouse move %.4f %.4f\nmouse move %.4f %.4f\n"
                "mouse release\nlayout\nquit\n",
                before.fx, before.fy, before.fx, before.fy + 0.1f, before.fx, before.fy + 0.4f);
  const EditorRun drag = run(script);
  ASSERT_EQ(drag.status, 0) << drag.err;
  const Light after = light_of(drag.out);
  EXPECT_EQ(after.selected, 1) << drag.out;
  EXPECT_LT(after.y, before.y - 0.5f) << drag.out;  // the light came down
  EXPECT_EQ(after.on_screen, 1) << drag.out;        // into view
}

// Every `stats` line's edit_to_first_image_ms.
std::vector<double> first_image_delays(const std::string& out) {
  std::vector<double> delays;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    const std::size_t at = line.find("edit_to_first_image_ms=");
    if (line.rfind("stats: ", 0) == 0 && at != std::string::npos) {
      delays.push_back(std::stod(line.substr(at + 23)));
    }
  }
  return delays;
}

// The afternoon's bug: after an edit in the snapshot | live view (which changes only the live
// B side) the delay was never measured, and the next view switch, seconds later, read as it
// (20 to 127 s). Each view's edit is measured from the edit to its image, and a later view
// switch is not an edit.
TEST_F(LayoutE2E, TheEditDelayIsMeasuredFromTheEditInEveryView) {
  const EditorRun r =
      run("wait\nset 0 shininess 20\nwait\nstats\n"
          "view terms\nwait\nset 0 shininess 30\nwait\nstats\n"
          "view term specular\nwait\nset 0 shininess 40\nwait\nstats\n"
          "view ab\nwait\nset 0 shininess 50\nwait\nstats\n"
          "snapshot\nview ab snapshot\nwait\nset 0 shininess 60\nwait\nstats\n"
          "sleep 3\nview render\nwait\nstats\nquit\n");
  if (r.status == -1) GTEST_SKIP() << "no xvfb-run";
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<double> d = first_image_delays(r.out);
  ASSERT_EQ(d.size(), 6u) << r.out;
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_GT(d[i], 0.0) << i << "\n" << r.out;
    EXPECT_LT(d[i], 2500.0) << i << "\n" << r.out;  // well under the 3 s the last line sleeps
  }
  EXPECT_NE(d[4], d[3]) << r.out;  // the snapshot view's edit was measured, not left at A/B's
  EXPECT_EQ(d[5], d[4]) << r.out;  // the view switch 3 s later is not an edit
}

}  // namespace
}  // namespace gloss

// End-to-end: the physical reference in the real gloss (issue 23's "done when"): measured gold of
// roughness 0.2 on the gold sphere, the material | reference A/B view, a fit that brings the
// Phong gold closer, under Xvfb and without a display.
#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <string>

#include "editor/e2e/editor_process.h"

namespace gloss {
namespace {

using test::EditorRun;

class ReferenceE2E : public test::EditorProcessTest {
 protected:
  ReferenceE2E() : EditorProcessTest("gloss-reference-e2e-") {}
  EditorRun run(const std::string& script_text, bool with_display = true) {
    return run_editor(std::string(GLOSS_SCENES_DIR) + "/spheres.json", script_text, with_display);
  }
};

// The values of every "ab_max_difference=D" in the `stats` lines of out, in order.
std::vector<double> ab_differences(const std::string& out) {
  std::vector<double> values;
  const std::string key = "ab_max_difference=";
  for (std::size_t at = out.find(key); at != std::string::npos; at = out.find(key, at + 1)) {
    values.push_back(std::strtod(out.c_str() + at + key.size(), nullptr));
  }
  return values;
}

// The preset gold beside measured gold: the reference's highlight is tens of times brighter
// than the preset's, so the heat map's largest difference is large; after Fit Phong the two are
// much closer (the fitted ks carries the peak).
TEST_F(ReferenceE2E, FitBringsThePhongGoldCloserToMeasuredGold) {
  const EditorRun r =
      run("select 0\nreference gold 0.2\nview ab reference\nwait\nstats\n"
          "fit phong\nwait\nstats\nscreenshot ab.png window\nundo\nundo\nwait\nquit\n");
  if (r.status == -1) GTEST_SKIP() << "no xvfb-run";
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<double> d = ab_differences(r.out);
  ASSERT_EQ(d.size(), 2u) << r.out;
  EXPECT_GT(d[0], 20.0) << r.out;
  EXPECT_LT(d[1], 0.7 * d[0]) << r.out;
  EXPECT_NE(r.out.find("fit: residual l2 "), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(m_dir / "ab.png"));
}

// Without a display the document lines run all the same.
TEST_F(ReferenceE2E, WithoutADisplayTheFitRuns) {
  const EditorRun r = run("reference copper 0.3\nfit blinn-phong lightness\nquit\n", false);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("fit: fit blinn-phong to copper roughness 0.3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("minimising lightness"), std::string::npos) << r.out;
}

TEST_F(ReferenceE2E, ABadReferenceLineNamesTheLine) {
  const EditorRun r = run("reference gold 0\nquit\n", false);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("script.txt:1: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("roughness"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace gloss

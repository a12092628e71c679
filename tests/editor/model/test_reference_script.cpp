// The physical reference's script lines (docs/editor.md): `reference METAL ROUGHNESS`,
// `reference dielectric R G B ROUGHNESS`, `reference none`, `fit phong|blinn-phong [METRIC]`,
// `view ab reference`; and the A/B view's reference comparison (ab_compare.h).
#include <gtest/gtest.h>

#include "base/error.h"
#include "editor/model/script/script.h"
#include "editor/model/script/script_runner.h"
#include "editor/model/view/ab_compare.h"
#include "support/quiet_script_host.h"
#include "support/test_scene.h"

namespace gloss {
namespace {

// Runs every line; returns the last result, with stdout and stderr.
LineResult run_all(const std::string& text, ScriptHost& host, std::string& out,
                   std::string& errors) {
  const Script s = parse_script(text, "run.txt");
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  LineResult result;
  for (const ScriptLine& line : s.lines) {
    result = run_script_line(s, line, host);
    if (result.next == LineResult::Next::stop) break;
  }
  out = testing::internal::GetCapturedStdout();
  errors = testing::internal::GetCapturedStderr();
  return result;
}

TEST(ReferenceScript, Parses) {
  const Script s = parse_script(
      "reference gold 0.2\nreference dielectric 0.6 0.1 0.1 0.5\nreference none\n"
      "fit phong\nfit blinn-phong lightness\nview ab reference\n",
      "r.txt");
  ASSERT_EQ(s.lines.size(), 6u);
  const ReferenceAction& gold = std::get<ReferenceAction>(s.lines[0].action);
  ASSERT_TRUE(gold.reference.has_value());
  EXPECT_EQ(gold.reference->kind, ReferenceKind::gold);
  EXPECT_EQ(gold.reference->roughness, 0.2f);
  const ReferenceAction& red = std::get<ReferenceAction>(s.lines[1].action);
  EXPECT_EQ(red.reference->kind, ReferenceKind::dielectric);
  EXPECT_EQ(red.reference->base, glm::vec3(0.6f, 0.1f, 0.1f));
  EXPECT_EQ(red.reference->roughness, 0.5f);
  EXPECT_FALSE(std::get<ReferenceAction>(s.lines[2].action).reference.has_value());
  EXPECT_EQ(std::get<FitAction>(s.lines[3].action).model, ShadingModel::phong);
  EXPECT_EQ(std::get<FitAction>(s.lines[3].action).metric, LobeMetric::l2);
  EXPECT_EQ(std::get<FitAction>(s.lines[4].action).model, ShadingModel::blinn_phong);
  EXPECT_EQ(std::get<FitAction>(s.lines[4].action).metric, LobeMetric::lightness);
  EXPECT_EQ(std::get<ViewAction>(s.lines[5].action).ab_source, AbSource::reference);
}

// The lobe view's radius scale: `view lobe [ELEVATION] [log|linear]`.
TEST(ReferenceScript, LobeViewLogRadius) {
  const Script s = parse_script("view lobe 30 log\nview lobe linear\nview lobe 60\n", "l.txt");
  const ViewAction& a = std::get<ViewAction>(s.lines[0].action);
  EXPECT_EQ(a.lobe_elevation_deg, 30.0f);
  EXPECT_EQ(a.lobe_log_radius, 1);
  const ViewAction& b = std::get<ViewAction>(s.lines[1].action);
  EXPECT_EQ(b.lobe_elevation_deg, -1.0f);
  EXPECT_EQ(b.lobe_log_radius, 0);
  EXPECT_EQ(std::get<ViewAction>(s.lines[2].action).lobe_log_radius, -1);
  EXPECT_THROW(parse_script("view lobe 30 loud\n", "l.txt"), InputError);
  test::QuietScriptHost host(test::two_sphere_scene());
  std::string out, errors;
  run_all("view lobe 20 log\n", host, out, errors);
  EXPECT_TRUE(host.view().lobe_log_radius);
  EXPECT_EQ(host.view().lobe_elevation_deg, 20.0f);
}

TEST(ReferenceScript, BadLinesNameTheLine) {
  const char* bad[] = {"reference gld 0.2",
                       "reference gold",
                       "reference gold 0",
                       "reference gold 1.5",
                       "reference dielectric 0.5 0.2",
                       "reference dielectric 2 0 0 0.3",
                       "reference gold 0.2 extra",
                       "fit",
                       "fit blin",
                       "fit phong l3",
                       "view ab referencee"};
  for (const char* line : bad) {
    try {
      parse_script(std::string("exposure 0\n") + line + "\n", "r.txt");
      ADD_FAILURE() << line << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), 2) << line;
    }
  }
}

// The "done when": gold at roughness 0.2 on the selected object, fit, the closest Phong
// gold with a number for how close, in one undoable step.
TEST(ReferenceScript, ReferenceThenFitIsOneUndoStepEach) {
  test::QuietScriptHost host(test::two_sphere_scene());
  const Scene before = host.layer().scene();
  std::string out, errors;
  const LineResult r = run_all("select 1\nreference gold 0.2\nfit phong\n", host, out, errors);
  EXPECT_EQ(r.next, LineResult::Next::go_on) << errors;
  const Material& m = host.layer().scene().materials[1];
  ASSERT_TRUE(m.reference.has_value());
  EXPECT_EQ(m.reference->kind, ReferenceKind::gold);
  // Gold's fitted highlight is red over green over blue, far above the classic ks <= 1.
  EXPECT_GT(m.specular.x, m.specular.y);
  EXPECT_GT(m.specular.y, m.specular.z);
  EXPECT_GT(m.specular.x, 10.0f);
  EXPECT_EQ(m.ambient, before.materials[1].ambient);  // ka kept
  EXPECT_NE(out.find("fit: residual l2 "), std::string::npos) << out;
  EXPECT_NE(out.find("Real-Time Rendering, 4th ed., Table 9.2"), std::string::npos) << out;
  EXPECT_EQ(host.layer().scene().render.model, ShadingModel::phong);
  EXPECT_NE(host.layer().undo_label().find("fit Phong to gold r 0.2"), std::string::npos)
      << host.layer().undo_label();
  ASSERT_TRUE(host.layer().undo());
  EXPECT_EQ(host.layer().scene().materials[1].specular, before.materials[1].specular);
  EXPECT_TRUE(host.layer().scene().materials[1].reference.has_value());
  ASSERT_TRUE(host.layer().undo());
  EXPECT_EQ(host.layer().scene().materials[1], before.materials[1]);
}

// Fit Blinn-Phong in a Phong scene switches the scene's model in the same step.
TEST(ReferenceScript, FitBlinnPhongSwitchesTheModel) {
  test::QuietScriptHost host(test::two_sphere_scene());
  std::string out, errors;
  ASSERT_EQ(
      run_all("reference dielectric 0.6 0.1 0.1 0.5\nfit blinn-phong\n", host, out, errors).next,
      LineResult::Next::go_on)
      << errors;
  EXPECT_EQ(host.layer().scene().render.model, ShadingModel::blinn_phong);
  ASSERT_TRUE(host.layer().undo());
  EXPECT_EQ(host.layer().scene().render.model, ShadingModel::phong);
}

TEST(ReferenceScript, FitWithoutAReferenceIsABadLine) {
  test::QuietScriptHost host(test::two_sphere_scene());
  std::string out, errors;
  const LineResult r = run_all("fit phong\n", host, out, errors);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(errors.rfind("error: run.txt:1: ", 0), 0u) << errors;
  EXPECT_NE(errors.find("no physical reference"), std::string::npos) << errors;
}

TEST(ReferenceScript, ViewAbReferenceRendersBothSidesAtOneSample) {
  Scene doc = test::two_sphere_scene();
  doc.render.spp = 16;
  const AbScenes pair = ab_scenes(doc, AbSource::reference, nullptr, true);
  EXPECT_EQ(pair.a.render.spp, 1);
  EXPECT_EQ(pair.b.render.spp, 1);
  EXPECT_EQ(pair.a.materials, doc.materials);  // the material as it is, in the scene's model
  const AbSides sides = ab_sides(AbSource::reference, true, ShadingFrequency::pixel);
  EXPECT_FALSE(sides.a.physical);
  EXPECT_FALSE(sides.a.raster);
  EXPECT_TRUE(sides.b.physical);
  EXPECT_EQ(ab_label_b(AbSource::reference, true), "B: physical reference (GGX), 1 spp");
  test::QuietScriptHost host(doc);
  std::string out, errors;
  run_all("view ab reference\n", host, out, errors);
  EXPECT_EQ(host.view().mode, ViewMode::ab);
  EXPECT_EQ(host.view().ab_source, AbSource::reference);
}

}  // namespace
}  // namespace gloss

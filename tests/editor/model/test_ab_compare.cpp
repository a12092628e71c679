// The A/B view's two documents: Phong | Blinn-Phong with the x4 exponent rule, and a snapshot |
// the live document, through the script lines `snapshot` and `view ab snapshot`. The snapshot
// comparison is checked on rendered images: an emission added after the snapshot is the whole
// difference.
#include <gtest/gtest.h>

#include "base/error.h"
#include "editor/model/script/script.h"
#include "editor/model/script/script_runner.h"
#include "editor/model/view/ab_compare.h"
#include "editor/model/view/heat_map.h"
#include "engine/renderer.h"
#include "support/quiet_script_host.h"
#include "support/script_checks.h"
#include "support/test_scene.h"

namespace gloss {
namespace {

using Host = test::QuietScriptHost;

int run(const std::string& text, Host& host, std::string& errors) {
  return test::run_script_text(text, "ab.txt", host, errors);
}

Image total(const Scene& scene) {
  RenderOptions options;
  options.terms = false;
  return render(scene, options).total;
}

TEST(AbCompare, ModelsCompareThePhongAndBlinnVersionsOfTheDocument) {
  const Scene doc = test::two_sphere_scene();  // Phong, exponents 64 and 10
  AbScenes kept = ab_scenes(doc, AbSource::models, nullptr, true);
  EXPECT_EQ(kept.a.render.model, ShadingModel::phong);
  EXPECT_EQ(kept.b.render.model, ShadingModel::blinn_phong);
  EXPECT_FLOAT_EQ(kept.a.materials[0].shininess, 64.0f);
  EXPECT_FLOAT_EQ(kept.b.materials[0].shininess, 256.0f);  // 4 x 64
  EXPECT_FLOAT_EQ(kept.b.materials[1].shininess, 40.0f);   // 4 x 10
  AbScenes same = ab_scenes(doc, AbSource::models, nullptr, false);
  EXPECT_FLOAT_EQ(same.b.materials[0].shininess, 64.0f);
  EXPECT_EQ(ab_label_b(AbSource::models, true), "B: Blinn-Phong (exponents x4)");
}

TEST(AbCompare, ViewAbSnapshotNeedsASnapshot) {
  Host host(test::two_sphere_scene());
  std::string errors;
  EXPECT_EQ(run("view ab snapshot\n", host, errors), 2);
  EXPECT_NE(errors.find("ab.txt:1: no snapshot"), std::string::npos) << errors;
  EXPECT_EQ(host.view().mode, ViewMode::render);
}

TEST(AbCompare, SnapshotIsASideAndTheLiveDocumentBSide) {
  Host host(test::two_sphere_scene());
  std::string errors;
  ASSERT_EQ(run("snapshot\nset 0 emission 0.25 0 0\nview ab snapshot\n", host, errors), 0)
      << errors;
  ASSERT_TRUE(host.snapshot().has_value());
  EXPECT_EQ(host.snapshot()->label, "snapshot 1");
  EXPECT_EQ(host.view().mode, ViewMode::ab);
  EXPECT_EQ(host.view().ab_source, AbSource::snapshot);
  const AbScenes pair = ab_scenes(host.layer().scene(), host.view().ab_source, &*host.snapshot(),
                                  host.view().keep_highlight_size);
  EXPECT_EQ(pair.a.materials[0].emission, glm::vec3(0.0f));  // before the edit
  EXPECT_EQ(pair.b.materials[0].emission, glm::vec3(0.25f, 0.0f, 0.0f));
  EXPECT_EQ(pair.a.render.model, pair.b.render.model);  // no exponent rule here
  // The emission adds 0.25 to the red channel of every pixel fully inside sphere 0 and nothing
  // elsewhere: the largest difference (the heat map's automatic scale) is 0.25.
  EXPECT_NEAR(max_difference(total(pair.a), total(pair.b)), 0.25f, 1e-5f);
  // A second snapshot of the same document compares equal to it: difference 0.
  ASSERT_EQ(run("snapshot\n", host, errors), 0);
  EXPECT_EQ(host.snapshot()->label, "snapshot 2");
  const AbScenes same =
      ab_scenes(host.layer().scene(), AbSource::snapshot, &*host.snapshot(), true);
  EXPECT_EQ(max_difference(total(same.a), total(same.b)), 0.0f);
}

TEST(AbCompare, PlainViewAbGoesBackToModels) {
  Host host(test::two_sphere_scene());
  std::string errors;
  ASSERT_EQ(run("snapshot\nview ab snapshot\nview ab\n", host, errors), 0) << errors;
  EXPECT_EQ(host.view().ab_source, AbSource::models);
}

TEST(AbCompare, CpuGlIsTheDocumentAtOneSampleAgainstTheRasterPath) {
  Scene doc = test::two_sphere_scene();
  doc.render.spp = 16;
  const AbScenes pair = ab_scenes(doc, AbSource::cpu_gl, nullptr, true);
  // A is traced at the pixel centre only (where the raster path samples); nothing else changes.
  EXPECT_EQ(pair.a.render.spp, 1);
  EXPECT_EQ(pair.b.render.spp, 16);
  EXPECT_EQ(pair.a.render.model, doc.render.model);
  EXPECT_FLOAT_EQ(pair.a.materials[0].shininess, doc.materials[0].shininess);
  EXPECT_FLOAT_EQ(pair.b.materials[0].shininess, doc.materials[0].shininess);
  const AbSides sides = ab_sides(AbSource::cpu_gl, false, ShadingFrequency::vertex);
  EXPECT_FALSE(sides.a.raster);
  EXPECT_TRUE(sides.b.raster);
  EXPECT_EQ(sides.b.shading, ShadingFrequency::vertex);  // the panel's frequency
  EXPECT_EQ(ab_label_a(AbSource::cpu_gl, nullptr), "A: ray traced, 1 spp");
  EXPECT_EQ(ab_label_b(AbSource::cpu_gl, true, ShadingFrequency::pixel),
            "B: raster (GLSL), per pixel");
  EXPECT_EQ(ab_label_b(AbSource::cpu_gl, true, ShadingFrequency::vertex),
            "B: raster (GLSL), per vertex");
}

TEST(AbCompare, PixelVertexIsTheRasterPathAtBothFrequencies) {
  const Scene doc = test::two_sphere_scene();
  const AbScenes pair = ab_scenes(doc, AbSource::pixel_vertex, nullptr, true);
  EXPECT_EQ(pair.a.render.spp, doc.render.spp);
  EXPECT_EQ(pair.b.render.model, doc.render.model);
  EXPECT_FLOAT_EQ(pair.b.materials[0].shininess, doc.materials[0].shininess);
  // Whatever the panel's frequency and renderer: A per pixel, B per vertex, both raster.
  for (bool raster : {false, true}) {
    const AbSides sides = ab_sides(AbSource::pixel_vertex, raster, ShadingFrequency::vertex);
    EXPECT_EQ(sides.a, (AbSide{true, ShadingFrequency::pixel}));
    EXPECT_EQ(sides.b, (AbSide{true, ShadingFrequency::vertex}));
  }
  EXPECT_EQ(ab_label_a(AbSource::pixel_vertex, nullptr), "A: raster, per pixel");
  EXPECT_EQ(ab_label_b(AbSource::pixel_vertex, true), "B: raster, per vertex (Gouraud)");
}

TEST(AbCompare, ModelsAndSnapshotFollowTheViewportsRenderer) {
  for (AbSource source : {AbSource::models, AbSource::snapshot}) {
    const AbSides cpu = ab_sides(source, false, ShadingFrequency::pixel);
    EXPECT_FALSE(cpu.a.raster);
    EXPECT_FALSE(cpu.b.raster);
    const AbSides gl = ab_sides(source, true, ShadingFrequency::vertex);
    EXPECT_EQ(gl.a, (AbSide{true, ShadingFrequency::vertex}));
    EXPECT_EQ(gl.b, (AbSide{true, ShadingFrequency::vertex}));
  }
}

TEST(AbCompare, ParsesTheNewViewLines) {
  const Script s =
      parse_script("view clipped on\nview clipped off\nview ab snapshot\nsnapshot\n", "v.txt");
  ASSERT_EQ(s.lines.size(), 4u);
  EXPECT_TRUE(std::get<ClippedOverlayAction>(s.lines[0].action).on);
  EXPECT_FALSE(std::get<ClippedOverlayAction>(s.lines[1].action).on);
  EXPECT_EQ(std::get<ViewAction>(s.lines[2].action).ab_source, AbSource::snapshot);
  EXPECT_TRUE(std::holds_alternative<SnapshotAction>(s.lines[3].action));
  EXPECT_THROW(parse_script("view clipped maybe\n", "v.txt"), InputError);
  EXPECT_THROW(parse_script("view ab yesterday\n", "v.txt"), InputError);
}

}  // namespace
}  // namespace gloss

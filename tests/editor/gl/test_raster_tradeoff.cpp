// The raster tradeoff rows (editor/gl/raster/raster_tradeoff.h) through EGL: the properties of the
// rows that follow from what each setting draws, checked on small images of the shipped scenes. No
// times are asserted (they depend on the machine); errors and agreement shares are deterministic.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>

#include "analysis/tradeoff/tradeoff.h"
#include "base/error.h"
#include "editor/gl/egl_context.h"
#include "editor/gl/raster/raster_tradeoff.h"
#include "editor/model/script/headless.h"
#include "editor/model/script/script.h"
#include "io/scene/scene_loader.h"

namespace gloss {
namespace {

Scene shipped(const char* name) {
  return load_scene(std::string(GLOSS_SCENES_DIR) + "/" + name);
}

// Small and quick: 96x54 pixels, one run, an 8-spp reference, two shadow map sizes, two biases.
RasterTradeoffOptions small_options() {
  RasterTradeoffOptions o;
  o.width = 96;
  o.height = 54;
  o.runs = 1;
  o.reference_spp = 8;
  o.tessellation_levels = {2, 16};
  o.shadow_map_sizes = {64, 512};
  o.shadow_biases = {0.5f, 1.5f};
  return o;
}

const RasterTradeoffRow& row(const std::vector<RasterTradeoffRow>& rows, const std::string& knob,
                             const std::string& setting) {
  const auto it = std::find_if(rows.begin(), rows.end(), [&](const RasterTradeoffRow& r) {
    return r.knob == knob && r.setting == setting;
  });
  if (it == rows.end()) throw std::runtime_error("no row " + knob + " " + setting);
  return *it;
}

class RasterTradeoffRows : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!m_context.ok()) GTEST_SKIP() << "no EGL surfaceless GL: " << m_context.error();
  }
  test::EglContext m_context;
};

TEST(RasterTradeoffPure, PercentWithinCountsPixelsWhoseEveryChannelIsWithinTolerance) {
  Image reference(2, 2, glm::vec3(0.5f));
  Image test = reference;
  test.at(0, 0).g += 0.0009f;                                 // within 1e-3
  test.at(1, 0).b -= 0.0011f;                                 // beyond
  test.at(0, 1).r = std::numeric_limits<float>::quiet_NaN();  // never within
  EXPECT_DOUBLE_EQ(percent_within(test, reference, 1e-3), 50.0);
  EXPECT_THROW(percent_within(Image(1, 2), reference, 1e-3), std::invalid_argument);
}

TEST(RasterTradeoffPure, SettingsCoverEveryKnobInOrderAndTessellationOnlyForTeapots) {
  RasterTradeoffOptions o;  // 4 sizes, 5 biases, 5 levels
  const std::vector<RasterTradeoffSetting> teapot =
      raster_tradeoff_settings(shipped("teapot.json"), o, 32);
  // cpu, 2 shading, 4 sizes + off, 5 biases, 5 levels x 2 frequencies.
  ASSERT_EQ(teapot.size(), 1u + 2u + 5u + 5u + 10u);
  EXPECT_EQ(teapot[0].knob, "cpu");
  EXPECT_TRUE(teapot[0].cpu);
  EXPECT_EQ(teapot[1].knob + " " + teapot[1].setting, "raster-shading pixel");
  EXPECT_EQ(teapot[7].knob + " " + teapot[7].setting, "raster-shadow-map off");
  EXPECT_EQ(teapot[10].knob + " " + teapot[10].setting, "raster-bias 1.5");
  EXPECT_EQ(teapot[22].knob + " " + teapot[22].setting, "raster-tessellation vertex 32");
  // The base: per-pixel, 1024 texels, bias 1.5, teapot 32; four rows name it.
  const int bases = static_cast<int>(std::count_if(
      teapot.begin(), teapot.end(), [](const RasterTradeoffSetting& s) { return s.base; }));
  EXPECT_EQ(bases, 4);
  EXPECT_EQ(raster_tradeoff_settings(shipped("spheres.json"), o, 0).size(), 13u);
  o.shadow_map_sizes = {8};
  EXPECT_THROW(raster_tradeoff_settings(shipped("spheres.json"), o, 0), std::invalid_argument);
}

TEST(RasterTradeoffPure, QualityRasterScriptLineNamesTheCsvAndOptionalSize) {
  const Script s =
      parse_script("quality raster out.csv\nquality raster big.csv 640 360 256\n", "t");
  ASSERT_EQ(s.lines.size(), 2u);
  const auto& a = std::get<QualityAction>(s.lines[0].action);
  EXPECT_EQ(a.verb, QualityAction::Verb::raster);
  EXPECT_EQ(a.path, "out.csv");
  EXPECT_EQ(a.width, 0);
  const auto& b = std::get<QualityAction>(s.lines[1].action);
  EXPECT_EQ(b.width, 640);
  EXPECT_EQ(b.height, 360);
  EXPECT_EQ(b.reference_spp, 256);
  EXPECT_THROW(parse_script("quality raster\n", "t"), InputError);
  EXPECT_THROW(parse_script("quality raster a.csv 640\n", "t"), InputError);
}

// Without a window there is no GL context to draw with: the line fails (status 1), naming why.
TEST(RasterTradeoffPure, QualityRasterFailsWithoutADisplay) {
  const Script script = parse_script("quality raster never-written.csv\n", "t");
  testing::internal::CaptureStderr();
  const int status = run_script_without_display(shipped("spheres.json"), script, "test");
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(status, 1);
  EXPECT_NE(err.find("needs the editor's window"), std::string::npos) << err;
  EXPECT_FALSE(std::ifstream("never-written.csv").good());
}

// The teapot at 2 segments per patch side has 8 triangles per patch: interpolated vertex colours
// cannot place its highlight, per-pixel shading of the same triangles can; refined to 16, the
// vertices sample the highlight and the Gouraud error falls.
TEST_F(RasterTradeoffRows, GouraudLosesMostOnTheCoarseTeapotAndRecoversWhenRefined) {
  const std::vector<RasterTradeoffRow> rows =
      measure_raster_tradeoff(shipped("teapot.json"), small_options());
  std::printf("%s", raster_tradeoff_table(rows).c_str());
  const double pixel2 = row(rows, "raster-tessellation", "pixel 2").error.rmse;
  const double vertex2 = row(rows, "raster-tessellation", "vertex 2").error.rmse;
  const double vertex16 = row(rows, "raster-tessellation", "vertex 16").error.rmse;
  EXPECT_GT(vertex2, pixel2);
  EXPECT_LT(vertex16, vertex2);
  // The base rows (per-pixel, the finest level 16, default map and bias) draw one image.
  EXPECT_EQ(row(rows, "raster-shading", "pixel").error.rmse,
            row(rows, "raster-tessellation", "pixel 16").error.rmse);
  EXPECT_EQ(row(rows, "raster-shading", "vertex").error.rmse, vertex16);
  // Every row has a frame time and an image.
  for (const RasterTradeoffRow& r : rows) {
    EXPECT_GT(r.time_ms, 0.0) << r.knob << " " << r.setting;
    EXPECT_EQ(r.error.pixels, 96u * 54u) << r.knob << " " << r.setting;
  }
}

// The cpu row is run_tradeoff's spp 1 row: the same render against the same reference.
TEST_F(RasterTradeoffRows, CpuRowMeasuresAgainstTheTradeoffReference) {
  const Scene scene = shipped("teapot.json");
  const RasterTradeoffOptions o = small_options();
  const std::vector<RasterTradeoffRow> rows = measure_raster_tradeoff(scene, o);
  TradeoffOptions t;
  t.width = o.width;
  t.height = o.height;
  t.runs = 1;
  t.reference_spp = o.reference_spp;
  t.tessellation_levels = o.tessellation_levels;
  t.spp_levels = {1};
  t.knobs = {Knob::spp};
  const std::vector<TradeoffRow> cpu = run_tradeoff(scene, t);
  ASSERT_EQ(cpu.size(), 1u);
  EXPECT_EQ(row(rows, "cpu", "1 spp").error.rmse, cpu[0].error.rmse);
  EXPECT_EQ(row(rows, "cpu", "1 spp").error.pct_pixels_off, cpu[0].error.pct_pixels_off);
}

// presets.json has shadows off and only spheres: no shadow map is drawn (every size, bias and
// 'off' give the per-pixel image) and the spheres are impostors shaded per pixel whatever the
// frequency. Shadow-free, the raster path agrees with the 1-spp exact image on at least 99.5 %
// of the pixels (issue 12, item 4).
TEST_F(RasterTradeoffRows, WithoutShadowsOrMeshesEveryRasterRowDrawsThePerPixelImage) {
  const std::vector<RasterTradeoffRow> rows =
      measure_raster_tradeoff(shipped("presets.json"), small_options());
  std::printf("%s", raster_tradeoff_table(rows).c_str());
  const RasterTradeoffRow& pixel = row(rows, "raster-shading", "pixel");
  for (const RasterTradeoffRow& r : rows) {
    if (r.knob == "cpu") continue;
    EXPECT_EQ(r.error.rmse, pixel.error.rmse) << r.knob << " " << r.setting;
    EXPECT_EQ(r.pct_agree, pixel.pct_agree) << r.knob << " " << r.setting;
    EXPECT_EQ(r.shadow_ms, 0.0) << r.knob << " " << r.setting;
  }
  EXPECT_GE(pixel.pct_agree, 99.5);
}

// spheres.json: two spheres cast shadows on a floor. Turning shadows off loses them (the largest
// error of the CPU knobs, docs/accuracy.md); a shadow map keeps them but for its edges.
TEST_F(RasterTradeoffRows, ShadowMapsCostLessErrorThanNoShadows) {
  const std::vector<RasterTradeoffRow> rows =
      measure_raster_tradeoff(shipped("spheres.json"), small_options());
  std::printf("%s", raster_tradeoff_table(rows).c_str());
  const RasterTradeoffRow& off = row(rows, "raster-shadow-map", "off");
  const RasterTradeoffRow& fine = row(rows, "raster-shadow-map", "512");
  EXPECT_LT(fine.error.rmse, off.error.rmse);
  EXPECT_GT(fine.pct_agree, off.pct_agree);
  EXPECT_EQ(off.shadow_ms, 0.0);
  EXPECT_GT(fine.shadow_ms, 0.0) << "a moved light redraws the shadow maps";
  EXPECT_EQ(
      std::count_if(rows.begin(), rows.end(),
                    [](const RasterTradeoffRow& r) { return r.knob == "raster-tessellation"; }),
      0);
}

// The Quality window draws the raster frames in slices between UI frames: a slice of 1 ms draws
// one configuration's frames at a time, and the rows come out as measured in one go.
TEST_F(RasterTradeoffRows, SlicesGiveTheRowsOfOneGoAndCancelStopsWithNone) {
  const Scene scene = shipped("spheres.json");
  const std::vector<RasterTradeoffRow> whole = measure_raster_tradeoff(scene, small_options());
  RasterTradeoff sliced;
  sliced.start(scene, small_options());
  EXPECT_TRUE(sliced.running());
  double last = 0.0;
  int slices = 0;
  while (sliced.running()) {
    if (!sliced.step(1.0)) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    EXPECT_GE(sliced.progress(), last);
    last = sliced.progress();
    slices += sliced.state() == RasterTradeoff::State::rendering ? 1 : 0;
  }
  ASSERT_EQ(sliced.state(), RasterTradeoff::State::done) << sliced.error();
  EXPECT_EQ(sliced.progress(), 1.0);
  EXPECT_GT(slices, 1);
  ASSERT_EQ(sliced.rows().size(), whole.size());
  for (std::size_t i = 0; i < whole.size(); ++i) {
    EXPECT_EQ(sliced.rows()[i].setting, whole[i].setting);
    EXPECT_EQ(sliced.rows()[i].error.rmse, whole[i].error.rmse) << whole[i].setting;
    EXPECT_EQ(sliced.rows()[i].pct_agree, whole[i].pct_agree) << whole[i].setting;
  }
  RasterTradeoff cancelled;
  cancelled.start(scene, small_options());
  cancelled.cancel();
  while (cancelled.running()) {
    if (!cancelled.step(1.0)) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  EXPECT_EQ(cancelled.state(), RasterTradeoff::State::cancelled);
  EXPECT_TRUE(cancelled.rows().empty());
}

TEST_F(RasterTradeoffRows, CsvHasTheTradeoffColumnsFirstAndOneLinePerRow) {
  const std::vector<RasterTradeoffRow> rows =
      measure_raster_tradeoff(shipped("presets.json"), small_options());
  const std::string csv = raster_tradeoff_to_csv(rows);
  EXPECT_EQ(csv.rfind("knob,setting,time_ms,rmse,psnr_db,max_abs,pct_pixels_off,", 0), 0u);
  EXPECT_EQ(static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')), rows.size() + 1);
  EXPECT_NE(csv.find("\ncpu,1 spp,"), std::string::npos);
  EXPECT_NE(csv.find("\nraster-shadow-map,off,"), std::string::npos);
}

}  // namespace
}  // namespace gloss

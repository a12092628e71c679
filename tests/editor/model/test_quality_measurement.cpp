// The Quality panel's measurement without GL: rows arrive per knob in run order, cancel stops
// early and joins the worker, staleness ignores what run_tradeoff overrides; the verdict, the
// commands of the Use buttons and the script lines. Expected values come from tradeoff.h's
// contract (every row changes one knob of the base, so each knob has exactly one base row) and
// from hand-built rows, never from the program's own output.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "base/error.h"
#include "editor/model/document/document.h"
#include "editor/model/measure/quality_measurement.h"
#include "editor/model/script/script.h"
#include "io/scene/scene_loader.h"
#include "support/test_scene.h"

namespace gloss {
namespace {

using Clock = std::chrono::steady_clock;

// Tiny settings: a 32-pixel-wide image, one run per row, a 4-spp reference. Each measurement
// takes well under a second even under AddressSanitizer.
TradeoffOptions tiny_options() {
  TradeoffOptions o;
  o.width = 32;
  o.runs = 1;
  o.reference_spp = 4;
  o.base_spp = 1;
  o.spp_levels = {1, 2};
  o.adaptive_spp = 4;
  o.adaptive_thresholds = {1.0f / 16};
  o.tessellation_levels = {2, 4};
  o.resolution_divisors = {2, 1};
  return o;
}

std::size_t knob_position(Knob knob) {
  const std::vector<Knob>& all = tradeoff_knobs();
  return static_cast<std::size_t>(std::find(all.begin(), all.end(), knob) - all.begin());
}

TEST(QualityMeasurement, RowsArriveInKnobOrderWithOneBaseRowPerKnob) {
  QualityMeasurement q;
  q.start(test::two_sphere_scene(), tiny_options());
  EXPECT_TRUE(q.running());
  // The UI's loop: rows are taken as they arrive and never taken back.
  std::size_t seen = 0;
  while (q.running()) {
    q.poll();
    EXPECT_GE(q.rows().size(), seen);
    seen = q.rows().size();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_EQ(q.state(), QualityMeasurement::State::done) << q.error();
  // Two spheres, no teapot: every knob but tessellation.
  const std::vector<Knob> expected{Knob::spp,     Knob::adaptive,   Knob::pow,    Knob::precision,
                                   Knob::shading, Knob::resolution, Knob::shadows};
  EXPECT_EQ(q.knobs(), expected);
  EXPECT_EQ(q.knobs_done(), 7);
  for (std::size_t i = 1; i < q.rows().size(); ++i) {
    EXPECT_LE(knob_position(q.rows()[i - 1].knob), knob_position(q.rows()[i].knob));
  }
  for (const Knob knob : expected) {
    const std::vector<TradeoffRow> rows = rows_of_knob(q.rows(), knob);
    ASSERT_FALSE(rows.empty()) << to_string(knob);
    EXPECT_EQ(std::count_if(rows.begin(), rows.end(),
                            [](const TradeoffRow& r) { return r.base_setting; }),
              1)
        << to_string(knob);
  }
  EXPECT_EQ(rows_of_knob(q.rows(), Knob::spp).size(), 2u);         // spp_levels {1, 2}
  EXPECT_EQ(rows_of_knob(q.rows(), Knob::resolution).size(), 2u);  // divisors {2, 1}
  EXPECT_EQ(q.width(), 32);
  EXPECT_EQ(q.height(), 24);  // the scene's 64 x 48 aspect
  EXPECT_FALSE(q.worker_alive());
}

TEST(QualityMeasurement, TeapotSceneListsEveryKnobItHas) {
  QualityMeasurement q;
  q.start(load_scene(std::string(GLOSS_SCENES_DIR) + "/teapot.json"), tiny_options());
  q.wait();
  ASSERT_EQ(q.state(), QualityMeasurement::State::done) << q.error();
  // Every knob but the environment's and the maps' (the teapot scene has neither).
  std::vector<Knob> expected;
  for (const Knob knob : tradeoff_knobs()) {
    if (knob != Knob::env_samples && knob != Knob::env_resolution && knob != Knob::map_filter &&
        knob != Knob::map_resolution) {
      expected.push_back(knob);
    }
  }
  EXPECT_EQ(q.knobs(), expected);
  for (const Knob knob : expected) {
    EXPECT_FALSE(rows_of_knob(q.rows(), knob).empty()) << to_string(knob);
  }
  EXPECT_EQ(rows_of_knob(q.rows(), Knob::tessellation).size(), 2u);  // levels {2, 4}
}

// Settings heavy enough (a 256-spp double reference at 256 px, five runs) that the measurement
// cannot end by itself within the time allowed for the cancel to take effect.
TradeoffOptions heavy_options() {
  TradeoffOptions o;
  o.width = 256;
  o.runs = 5;
  o.reference_spp = 256;
  return o;
}

TEST(QualityMeasurement, CancelStopsEarlyAndJoinsTheWorker) {
  QualityMeasurement q;
  q.start(test::two_sphere_scene(), heavy_options());
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  q.poll();
  ASSERT_TRUE(q.running());
  const Clock::time_point asked = Clock::now();
  q.cancel();
  q.wait();
  const double seconds = std::chrono::duration<double>(Clock::now() - asked).count();
  EXPECT_EQ(q.state(), QualityMeasurement::State::cancelled);
  EXPECT_FALSE(q.worker_alive());
  EXPECT_LT(q.knobs_done(), 7);
  EXPECT_LT(seconds, 5.0);
}

TEST(QualityMeasurement, DestroyingWhileRunningCancelsAndJoins) {
  const Clock::time_point begin = Clock::now();
  {
    QualityMeasurement q;
    q.start(test::two_sphere_scene(), heavy_options());
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - begin).count(), 5.0);
}

TEST(QualityMeasurement, RestartReplacesTheRunningMeasurement) {
  QualityMeasurement q;
  q.start(test::two_sphere_scene(), heavy_options());
  q.start(test::two_sphere_scene(), tiny_options());
  q.wait();
  EXPECT_EQ(q.state(), QualityMeasurement::State::done);
  EXPECT_EQ(q.width(), 32);
  EXPECT_EQ(rows_of_knob(q.rows(), Knob::spp).size(), 2u);
}

TEST(QualityMeasurement, BadOptionsFailWithTheMessage) {
  TradeoffOptions o = tiny_options();
  o.runs = 0;
  QualityMeasurement q;
  q.start(test::two_sphere_scene(), o);
  q.wait();
  EXPECT_EQ(q.state(), QualityMeasurement::State::failed);
  EXPECT_NE(q.error().find("runs"), std::string::npos) << q.error();
}

TEST(QualityMeasurement, StaleOnlyWhenWhatWasMeasuredChanged) {
  const Scene scene = test::two_sphere_scene();
  QualityMeasurement q;
  EXPECT_FALSE(q.stale(scene));  // nothing measured
  q.start(scene, tiny_options());
  q.wait();
  EXPECT_FALSE(q.stale(scene));
  Scene other = scene;
  other.render.spp = 16;  // run_tradeoff sets spp, sampling, threshold and pow itself
  other.render.pow = PowMode::fast;
  other.render.sampling = Sampling::uniform;
  other.render.aa_threshold = 0.25f;
  EXPECT_FALSE(q.stale(other));
  Scene toned = scene;  // adaptive placement reads the displayed image
  toned.render.tone = ToneCurve::aces;
  EXPECT_TRUE(q.stale(toned));
  other.materials[0].diffuse = glm::vec3(0.9f);
  EXPECT_TRUE(q.stale(other));
  Scene no_shadows = scene;
  no_shadows.render.shadows = false;  // the reference follows the scene's shadows
  EXPECT_TRUE(q.stale(no_shadows));
}

TradeoffRow row(const std::string& knob, const std::string& setting, double ms, double pct,
                double rmse = 0.0, bool reference = false) {
  TradeoffRow r;
  EXPECT_TRUE(parse_knob(knob, r.knob)) << knob;
  r.setting = setting;
  r.time_ms = ms;
  r.error.pct_pixels_off = pct;
  r.error.rmse = rmse;
  r.reference_setting = reference;
  return r;
}

TEST(QualityVerdict, CheapestWithinOneLevelOnNinetyNinePercent) {
  // 2 is the cheapest with at most 1% of pixels off; 4 is more accurate but dearer.
  const std::string v = quality_verdict(
      {row("spp", "1", 1.0, 30.0), row("spp", "2", 2.0, 0.9), row("spp", "4", 4.0, 0.1)});
  EXPECT_EQ(v, "2: the cheapest within 1/255 on 99% of pixels (2.00 ms)");
}

TEST(QualityVerdict, OtherwiseTheCheapestAsGoodAsTheReferenceSetting) {
  // Reference c: 2% off, RMSE 0.010, 9 ms. b: 2.5% (<= 3) and 0.011 (<= 0.015) at 3 ms (<= 8.55):
  // as good and cheaper. a: 5% off, not as good. d: as good but 11 ms, dearer.
  const std::string v =
      quality_verdict({row("spp", "a", 1.0, 5.0, 0.02), row("spp", "b", 3.0, 2.5, 0.011),
                       row("spp", "c", 9.0, 2.0, 0.010, true), row("spp", "d", 11.0, 2.0, 0.010)});
  EXPECT_EQ(v, "b: as good as c at 3.00 ms vs 9.00 ms");
  // b at 8.8 ms is less than 5% cheaper than c: keep the reference setting.
  EXPECT_EQ(
      quality_verdict({row("spp", "b", 8.8, 2.5, 0.011), row("spp", "c", 9.0, 2.0, 0.010, true)}),
      "keep c: nothing 5% cheaper is as good");
  // b with 1.6x the RMSE is not as good.
  EXPECT_EQ(
      quality_verdict({row("spp", "b", 1.0, 2.5, 0.016), row("spp", "c", 9.0, 2.0, 0.010, true)}),
      "keep c: nothing 5% cheaper is as good");
  // Without a reference row the most accurate row (e) is the anchor.
  EXPECT_EQ(quality_verdict({row("spp", "e", 20.0, 1.5, 0.010), row("spp", "f", 10.0, 2.4, 0.012)}),
            "f: as good as e at 10 ms vs 20 ms");
  EXPECT_EQ(quality_verdict({}), "");
}

TEST(QualityUse, RowsBecomeCommandsOrPreviewScales) {
  const Scene scene = test::two_sphere_scene();
  const std::optional<Command> shadows = command_for_row(row("shadows", "off", 0, 0), scene);
  ASSERT_TRUE(shadows);
  EXPECT_EQ(std::get<SetField>(*shadows).key, "shadows");
  EXPECT_EQ(std::get<SetField>(*shadows).value.x, 0.0);
  const std::optional<Command> pow = command_for_row(row("pow", "fast", 0, 0), scene);
  ASSERT_TRUE(pow);
  Scene applied = scene;
  apply_command(*pow, applied);
  EXPECT_EQ(applied.render.pow, PowMode::fast);
  applied.render.pow = scene.render.pow;
  EXPECT_TRUE(same_scene(applied, scene));  // nothing else changed
  EXPECT_FALSE(command_for_row(row("tessellation", "8", 0, 0), scene));
  EXPECT_FALSE(command_for_row(row("precision", "double", 0, 0), scene));

  EXPECT_EQ(preview_scale_for_row(row("resolution", "1/2", 0, 0)), 0.5f);
  EXPECT_EQ(preview_scale_for_row(row("resolution", "1/4", 0, 0)), 0.25f);
  EXPECT_EQ(preview_scale_for_row(row("resolution", "1", 0, 0)), 1.0f);
  EXPECT_FALSE(preview_scale_for_row(row("resolution", "1/8", 0, 0)));  // below the slider's 0.25
  EXPECT_FALSE(preview_scale_for_row(row("spp", "2", 0, 0)));

  EXPECT_TRUE(row_in_use(row("spp", "1", 0, 0), scene, 1.0f));  // the scene's default spp is 1
  EXPECT_FALSE(row_in_use(row("spp", "8", 0, 0), scene, 1.0f));
  EXPECT_TRUE(row_in_use(row("resolution", "1/2", 0, 0), scene, 0.5f));
  EXPECT_TRUE(row_in_use(row("pow", "exact", 0, 0), scene, 1.0f));
}

// The afternoon's bug: "Use" on an spp row set the spp alone, so a scene with adaptive sampling
// rendered adaptively what was measured uniformly, and the row never showed "in use".
TEST(QualityUse, UseAppliesExactlyTheMeasuredSamplingAndMarksTheRow) {
  Scene scene = test::two_sphere_scene();
  scene.render.spp = 16;
  scene.render.sampling = Sampling::adaptive;
  const TradeoffRow spp8 = row("spp", "8", 0, 0);
  const std::optional<Command> use = command_for_row(spp8, scene);
  ASSERT_TRUE(use);
  Scene applied = scene;
  apply_command(*use, applied);
  EXPECT_EQ(applied.render.spp, 8);
  EXPECT_EQ(applied.render.sampling, Sampling::uniform);
  EXPECT_TRUE(row_in_use(spp8, applied, 1.0f));
  EXPECT_FALSE(row_in_use(spp8, scene, 1.0f));
  applied.render.spp = scene.render.spp;
  applied.render.sampling = scene.render.sampling;
  EXPECT_TRUE(same_scene(applied, scene));  // nothing else changed

  // An adaptive row: its spp, adaptive sampling and its refine threshold.
  const TradeoffRow adaptive = row("adaptive", "16 t=1/16", 0, 0);
  Scene uniform = applied;
  uniform.render.sampling = Sampling::uniform;
  EXPECT_FALSE(row_in_use(adaptive, uniform, 1.0f));
  const std::optional<Command> use_adaptive = command_for_row(adaptive, uniform);
  ASSERT_TRUE(use_adaptive);
  apply_command(*use_adaptive, uniform);
  EXPECT_EQ(uniform.render.spp, 16);
  EXPECT_EQ(uniform.render.sampling, Sampling::adaptive);
  EXPECT_EQ(uniform.render.aa_threshold, 0.0625f);
  EXPECT_TRUE(row_in_use(adaptive, uniform, 1.0f));
  EXPECT_FALSE(row_in_use(row("adaptive", "16 t=1/64", 0, 0), uniform, 1.0f));
  // Its "uniform" row is the base: 4 spp, uniform.
  const std::optional<Command> base = command_for_row(row("adaptive", "uniform", 0, 0), uniform);
  ASSERT_TRUE(base);
  apply_command(*base, uniform);
  EXPECT_EQ(uniform.render.spp, 4);
  EXPECT_EQ(uniform.render.sampling, Sampling::uniform);
  EXPECT_TRUE(row_in_use(row("spp", "4", 0, 0), uniform, 1.0f));
}

TEST(QualityScript, ParsesQualityLinesAndRejectsOthers) {
  const Script s = parse_script(
      "quality measure\nquality start\nquality cancel\nquality csv out/q.csv\n", "q.txt");
  ASSERT_EQ(s.lines.size(), 4u);
  EXPECT_EQ(std::get<QualityAction>(s.lines[0].action).verb, QualityAction::Verb::measure);
  EXPECT_EQ(std::get<QualityAction>(s.lines[1].action).verb, QualityAction::Verb::start);
  EXPECT_EQ(std::get<QualityAction>(s.lines[2].action).verb, QualityAction::Verb::cancel);
  EXPECT_EQ(std::get<QualityAction>(s.lines[3].action).verb, QualityAction::Verb::csv);
  EXPECT_EQ(std::get<QualityAction>(s.lines[3].action).path, "out/q.csv");
  EXPECT_THROW(parse_script("quality\n", "q.txt"), InputError);
  EXPECT_THROW(parse_script("quality csv\n", "q.txt"), InputError);
  EXPECT_THROW(parse_script("quality measure now\n", "q.txt"), InputError);
  EXPECT_THROW(parse_script("quality plot x.png\n", "q.txt"), InputError);
}

TEST(QualityCsv, WritesTheTradeoffHeaderAndOneLinePerRow) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "gloss-quality-test.csv").string();
  write_quality_csv(path, {row("spp", "1", 2.5, 10.0), row("shadows", "off", 1.0, 3.0)});
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::filesystem::remove(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(text, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "knob,setting,time_ms,rmse,psnr_db,max_abs,pct_pixels_off");
  EXPECT_EQ(lines[1].rfind("spp,1,2.500,", 0), 0u) << lines[1];
  EXPECT_EQ(lines[2].rfind("shadows,off,1.000,", 0), 0u) << lines[2];
}

}  // namespace
}  // namespace gloss

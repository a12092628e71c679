// run_tradeoff on a small teapot scene: every knob and setting present, errors that behave as the
// knobs say (more samples, less error; the reference's own settings next to nothing), the CSV
// header of the issue, and cancellation from the caller.
#include "analysis/tradeoff/tradeoff.h"

#include <atomic>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/scene/scene_loader.h"
#include "support/scene_fixtures.h"
#include "texture/mip_pyramid.h"

namespace gloss {
namespace {

Scene small_teapot() {
  return load_scene(std::string(GLOSS_ASSETS_DIR) + "/scenes/teapot.json");
}

// Base spp = reference spp, so each knob's reference setting renders the reference's
// configuration with the fast float renderer.
TradeoffOptions small_options() {
  TradeoffOptions o;
  o.width = 40;
  o.height = 30;
  o.runs = 1;
  o.reference_spp = 16;
  o.base_spp = 16;
  o.spp_levels = {1, 4, 16};
  o.adaptive_thresholds = {1.0f / 16, 1.0f / 64};
  o.tessellation_levels = {2, 4, 8};
  o.resolution_divisors = {4, 2, 1};
  return o;
}

class Tradeoff : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    rows = new std::vector<TradeoffRow>(run_tradeoff(small_teapot(), small_options()));
  }
  static void TearDownTestSuite() { delete rows; }
  static const TradeoffRow& row(const std::string& knob, const std::string& setting) {
    for (const TradeoffRow& r : *rows) {
      if (to_string(r.knob) == knob && r.setting == setting) return r;
    }
    throw std::out_of_range(knob + " " + setting);
  }
  static std::vector<TradeoffRow>* rows;
};
std::vector<TradeoffRow>* Tradeoff::rows = nullptr;

TEST_F(Tradeoff, AdaptiveSamplingBeatsTheCentreSampleAndItsBaseRowIsTheBase) {
  // 16 samples where the centre image has edges: nearer the reference than the centres alone.
  EXPECT_LT(row("adaptive", "16 t=1/16").error.rmse, row("spp", "1").error.rmse);
  EXPECT_LE(row("adaptive", "16 t=1/64").error.rmse, row("adaptive", "16 t=1/16").error.rmse);
  EXPECT_TRUE(row("adaptive", "uniform").base_setting);
  EXPECT_FALSE(row("adaptive", "16 t=1/64").base_setting);
}

TEST_F(Tradeoff, EveryKnobIsPresentWithItsSettingsInOrder) {
  std::map<std::string, std::vector<std::string>> got;
  std::vector<std::string> order;
  for (const TradeoffRow& r : *rows) {
    if (got[to_string(r.knob)].empty()) order.push_back(to_string(r.knob));
    got[to_string(r.knob)].push_back(r.setting);
  }
  EXPECT_EQ(order, (std::vector<std::string>{"spp", "adaptive", "tessellation", "pow", "precision",
                                             "shading", "resolution", "shadows"}));
  EXPECT_EQ(got["spp"], (std::vector<std::string>{"1", "4", "16"}));
  EXPECT_EQ(got["adaptive"], (std::vector<std::string>{"uniform", "16 t=1/16", "16 t=1/64"}));
  EXPECT_EQ(got["tessellation"], (std::vector<std::string>{"2", "4", "8"}));
  EXPECT_EQ(got["pow"], (std::vector<std::string>{"exact", "fast"}));
  EXPECT_EQ(got["precision"], (std::vector<std::string>{"float", "double"}));
  EXPECT_EQ(got["shading"], (std::vector<std::string>{"per-pixel", "gouraud"}));
  EXPECT_EQ(got["resolution"], (std::vector<std::string>{"1/4", "1/2", "1"}));
  EXPECT_EQ(got["shadows"], (std::vector<std::string>{"on", "off"}));
  for (const TradeoffRow& r : *rows) {
    EXPECT_GT(r.time_ms, 0.0) << to_string(r.knob) << " " << r.setting;
    EXPECT_EQ(r.error.pixels, 40u * 30u);
  }
}

TEST_F(Tradeoff, ErrorDecreasesWithSamplesPerPixel) {
  EXPECT_GT(row("spp", "1").error.rmse, row("spp", "4").error.rmse);
  EXPECT_GT(row("spp", "4").error.rmse, row("spp", "16").error.rmse);
}

// The reference's setting of each knob differs from the reference only by float against double
// at the same samples (spec: 1e-4 on interior pixels), and the double row is the reference's own
// computation.
TEST_F(Tradeoff, ReferenceSettingOfEveryKnobHasAlmostNoError) {
  int marked = 0;
  for (const TradeoffRow& r : *rows) {
    if (!r.reference_setting) continue;
    ++marked;
    EXPECT_LT(r.error.max_abs, 1e-4) << to_string(r.knob) << " " << r.setting;
  }
  EXPECT_EQ(marked, 7);  // one per knob
  EXPECT_EQ(row("precision", "double").error.rmse, 0.0);
}

// The base is the reference's configuration but for the renderer (fast float) and its spp.
TEST_F(Tradeoff, BaseRowsAreTheReferenceSettingsButFloatAndTheBaseSpp) {
  std::vector<std::string> base;
  for (const TradeoffRow& r : *rows) {
    if (r.base_setting) base.push_back(std::string(to_string(r.knob)) + "=" + r.setting);
  }
  EXPECT_EQ(base, (std::vector<std::string>{"spp=16", "adaptive=uniform", "tessellation=8",
                                            "pow=exact", "precision=float", "shading=per-pixel",
                                            "resolution=1", "shadows=on"}));
}

// Each knob turned away from the reference costs accuracy: clearly more error than its
// reference setting (shadows off loses the teapot's shadow; 2 segments per patch are a coarse
// polyhedron; a quarter of the pixels blurs every edge; Gouraud flattens the floor's lighting).
TEST_F(Tradeoff, SettingsAwayFromTheReferenceCostAccuracy) {
  const double base = row("spp", "16").error.rmse + 1e-6;
  for (const auto& [knob, setting] :
       std::vector<std::pair<std::string, std::string>>{{"spp", "1"},
                                                        {"tessellation", "2"},
                                                        {"shading", "gouraud"},
                                                        {"resolution", "1/4"},
                                                        {"shadows", "off"}}) {
    EXPECT_GT(row(knob, setting).error.rmse, 10 * base) << knob << " " << setting;
  }
}

TEST_F(Tradeoff, CsvHasTheIssuesHeaderAndOneLinePerRow) {
  const std::string csv = tradeoff_to_csv(*rows);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "knob,setting,time_ms,rmse,psnr_db,max_abs,pct_pixels_off");
  std::size_t lines = 0;
  for (char c : csv) lines += c == '\n' ? 1 : 0;
  EXPECT_EQ(lines, rows->size() + 1);
  EXPECT_NE(csv.find("\nprecision,double,"), std::string::npos);
  EXPECT_NE(csv.find(",inf,0,0.0000\n"), std::string::npos);  // the exact match: rmse 0
}

TEST(TradeoffControl, ReturningFalseFromOnRowStopsAfterThatRow) {
  TradeoffOptions o = small_options();
  o.knobs = {Knob::pow, Knob::shadows};
  int calls = 0;
  const std::vector<TradeoffRow> rows =
      run_tradeoff(small_teapot(), o, [&](const TradeoffRow&) { return ++calls < 3; });
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].knob, Knob::pow);
  EXPECT_EQ(rows[2].knob, Knob::shadows);
}

TEST(TradeoffControl, ACancelFlagSetBeforehandStopsBeforeAnyRow) {
  TradeoffOptions o = small_options();
  std::atomic<bool> cancel{true};
  o.cancel = &cancel;
  EXPECT_TRUE(run_tradeoff(small_teapot(), o).empty());
}

TEST(TradeoffControl, SceneWithoutTeapotSkipsTessellationAndSaysSo) {
  Scene scene = test::head_on_sphere_scene();
  TradeoffOptions o = small_options();
  o.knobs = {Knob::tessellation, Knob::pow};
  const std::vector<TradeoffRow> rows = run_tradeoff(scene, o);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].knob, Knob::pow);
  bool said = false;
  for (const std::string& note : tradeoff_notes(scene, o)) {
    said = said || note.find("tessellation: skipped") != std::string::npos;
  }
  EXPECT_TRUE(said);
}

TEST(TradeoffControl, OptionsOutOfRangeAreRefused) {
  const Scene scene = test::head_on_sphere_scene();
  TradeoffOptions o = small_options();
  o.runs = 0;
  EXPECT_THROW(run_tradeoff(scene, o), std::invalid_argument);
  o = small_options();
  o.tessellation_levels = {0};
  EXPECT_THROW(run_tradeoff(scene, o), std::invalid_argument);
}

// The map knobs on a sphere under a fine checker seen whole (minified): reading the maps nearest
// or bilinear at level 0 aliases, so both cost accuracy against trilinear (the contract's and the
// base's setting); maps at 1/8 of their size lose the detail the reference shows. A scene
// without maps has no map rows and says so.
TEST(TradeoffControl, MapKnobsWeighFilteringAndMapResolution) {
  Scene scene = test::head_on_sphere_scene();
  scene.render.shadows = false;
  FloatImage image;
  image.width = image.height = 256;
  image.channels = 1;
  for (int j = 0; j < 256; ++j) {
    for (int i = 0; i < 256; ++i) image.samples.push_back(((i / 2 + j / 2) % 2) ? 0.9f : 0.1f);
  }
  TextureMap& map = scene.materials[0].map(MapSlot::diffuse);
  map.file = "checker";
  map.texture = std::make_shared<Texture>(make_texture(std::move(image)));
  TradeoffOptions o = small_options();
  o.knobs = {Knob::map_filter, Knob::map_resolution};
  const std::vector<TradeoffRow> rows = run_tradeoff(scene, o);
  std::map<std::string, const TradeoffRow*> by;
  for (const TradeoffRow& r : rows) by[std::string(to_string(r.knob)) + " " + r.setting] = &r;
  ASSERT_EQ(rows.size(), 3u + 4u);
  const TradeoffRow& trilinear = *by.at("map_filter trilinear");
  EXPECT_TRUE(trilinear.reference_setting);
  EXPECT_TRUE(trilinear.base_setting);
  EXPECT_GT(by.at("map_filter nearest")->error.rmse, 2.0 * trilinear.error.rmse);
  EXPECT_GT(by.at("map_filter bilinear")->error.rmse, 2.0 * trilinear.error.rmse);
  EXPECT_TRUE(by.at("map_resolution 1")->base_setting);
  EXPECT_GT(by.at("map_resolution 1/8")->error.rmse, by.at("map_resolution 1")->error.rmse);

  const Scene plain = test::head_on_sphere_scene();
  EXPECT_TRUE(run_tradeoff(plain, o).empty());
  bool said = false;
  for (const std::string& note : tradeoff_notes(plain, o)) {
    said = said || note.find("map_filter, map_resolution: skipped") != std::string::npos;
  }
  EXPECT_TRUE(said);
}

// The names tables, CSV files and the Quality window print are the knobs' only spelling.
TEST(TradeoffKnobs, NamesReadBackAndUnknownNamesAreRefused) {
  for (const Knob knob : tradeoff_knobs()) {
    Knob parsed = Knob::spp;
    EXPECT_TRUE(parse_knob(to_string(knob), parsed)) << to_string(knob);
    EXPECT_EQ(parsed, knob);
  }
  Knob untouched = Knob::shadows;
  EXPECT_FALSE(parse_knob("colour", untouched));
  EXPECT_FALSE(parse_knob("SPP", untouched));
  EXPECT_EQ(untouched, Knob::shadows);
  EXPECT_STREQ(to_string(Knob::resolution), "resolution");
}

}  // namespace
}  // namespace gloss

// A tweaked preset reads as "(modified)"; the preset's own values, or values typed back to
// them, read as the preset. Needs the shipped preset table (GLOSS_ASSETS).
#include <gtest/gtest.h>

#include "editor/model/preset_status.h"
#include "io/preset_table.h"

#include <cmath>

namespace gloss {
namespace {

TEST(PresetStatus, ThePresetsOwnValuesAreNotModified) {
  const Preset* gold = find_preset("gold");
  ASSERT_NE(gold, nullptr);
  EXPECT_FALSE(preset_modified(gold->material));
  EXPECT_EQ(preset_status(gold->material), "gold");
}

TEST(PresetStatus, AnyChangedConstantIsModified) {
  const Material gold = find_preset("gold")->material;
  Material m = gold;
  m.shininess += 1.0f;
  EXPECT_TRUE(preset_modified(m));
  EXPECT_EQ(preset_status(m), "gold (modified)");
  m = gold;
  m.emission = glm::vec3(0.1f, 0.0f, 0.0f);
  EXPECT_TRUE(preset_modified(m));
  m = gold;
  m.diffuse.b += 0.001f;
  EXPECT_TRUE(preset_modified(m));
  m.diffuse = gold.diffuse;  // typed back: the preset again
  EXPECT_FALSE(preset_modified(m));
}

TEST(PresetStatus, AMaterialWithoutAPresetHasNoStatus) {
  Material m;
  EXPECT_FALSE(preset_modified(m));
  EXPECT_EQ(preset_status(m), "");
  m.preset = "no_such_preset";
  EXPECT_FALSE(preset_modified(m));
}

}  // namespace
}  // namespace gloss

#include "editor/model/log_drag.h"

namespace gloss {
namespace {

TEST(LogDrag, APixelIsOnePercentOfTheValueAnywhereOnTheRange) {
  // The old slider: ln(10000 / 0.1) over ~150 px = 8% per pixel. Now 1% at every value.
  EXPECT_FLOAT_EQ(log_drag_speed(5.0f, 0.01f), 0.05f);
  EXPECT_FLOAT_EQ(log_drag_speed(5000.0f, 0.01f), 50.0f);
  EXPECT_FLOAT_EQ(log_drag_speed(0.0f, 0.01f), 0.01f);  // the floor lets a drag leave 0
  // 100 px to the right from 51.2 multiply it by about 1.01^100 = 2.7 (frame by frame).
  float v = 51.2f;
  for (int px = 0; px < 100; ++px) v += log_drag_speed(v, 0.01f);
  EXPECT_NEAR(v, 51.2f * std::pow(1.01f, 100.0f), 0.01f);
}

}  // namespace
}  // namespace gloss

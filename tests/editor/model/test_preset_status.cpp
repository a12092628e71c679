// A tweaked preset reads as "(modified)"; the preset's own values, or values typed back to
// them, read as the preset. Needs the shipped preset table (GLOSS_ASSETS).
#include <gtest/gtest.h>

#include "editor/model/document/preset_status.h"
#include "io/material/preset_table.h"

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

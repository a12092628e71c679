#include "io/material/preset_table.h"

#include <cstdlib>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "base/assets.h"
#include "base/error.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

// Typed from the team's copy of the teapots.c table (the data of
// assets/materials/opengl-vrml.csv, whose header names its origin), not read from the shipped
// file: name and the table's shininess fraction, in table order.
struct NamedShininess {
  const char* name;
  float raw;
};
const NamedShininess table_shininess[] = {
    {"emerald", 0.6f},
    {"jade", 0.1f},
    {"obsidian", 0.3f},
    {"pearl", 0.088f},
    {"ruby", 0.6f},
    {"turquoise", 0.1f},
    {"brass", 0.21794872f},
    {"bronze", 0.2f},
    {"chrome", 0.6f},
    {"copper", 0.1f},
    {"gold", 0.4f},
    {"silver", 0.4f},
    {"black_plastic", 0.25f},
    {"cyan_plastic", 0.25f},
    {"green_plastic", 0.25f},
    {"red_plastic", 0.25f},
    {"white_plastic", 0.25f},
    {"yellow_plastic", 0.25f},
    {"black_rubber", 0.078125f},
    {"cyan_rubber", 0.078125f},
    {"green_rubber", 0.078125f},
    {"red_rubber", 0.078125f},
    {"white_rubber", 0.078125f},
    {"yellow_rubber", 0.078125f},
};

// Phong exponents = fraction x 128, multiplied out by hand.
const float table_exponents[] = {76.8f, 12.8f, 38.4f, 11.264f, 76.8f, 12.8f, 27.89743616f, 25.6f,
                                 76.8f, 12.8f, 51.2f, 51.2f,   32.0f, 32.0f, 32.0f,        32.0f,
                                 32.0f, 32.0f, 10.0f, 10.0f,   10.0f, 10.0f, 10.0f,        10.0f};

struct FullRow {
  const char* name;
  glm::vec3 ambient, diffuse, specular;
  float shininess;  // Phong exponent
};
const FullRow full_rows[] = {
    {"gold",
     {0.24725f, 0.1995f, 0.0745f},
     {0.75164f, 0.60648f, 0.22648f},
     {0.628281f, 0.555802f, 0.366065f},
     51.2f},
    {"silver",
     {0.19225f, 0.19225f, 0.19225f},
     {0.50754f, 0.50754f, 0.50754f},
     {0.508273f, 0.508273f, 0.508273f},
     51.2f},
    {"emerald",
     {0.0215f, 0.1745f, 0.0215f},
     {0.07568f, 0.61424f, 0.07568f},
     {0.633f, 0.727811f, 0.633f},
     76.8f},
    {"brass",
     {0.329412f, 0.223529f, 0.027451f},
     {0.780392f, 0.568627f, 0.113725f},
     {0.992157f, 0.941176f, 0.807843f},
     27.89743616f},
    {"pearl",
     {0.25f, 0.20725f, 0.20725f},
     {1.0f, 0.829f, 0.829f},
     {0.296648f, 0.296648f, 0.296648f},
     11.264f},
    {"black_plastic", {0.0f, 0.0f, 0.0f}, {0.01f, 0.01f, 0.01f}, {0.5f, 0.5f, 0.5f}, 32.0f},
    {"cyan_plastic",
     {0.0f, 0.1f, 0.06f},
     {0.0f, 0.50980392f, 0.50980392f},
     {0.50196078f, 0.50196078f, 0.50196078f},
     32.0f},
    {"yellow_rubber", {0.05f, 0.05f, 0.0f}, {0.5f, 0.5f, 0.4f}, {0.7f, 0.7f, 0.04f}, 10.0f},
};

std::string data_file(const std::string& name) {
  return std::string(GLOSS_TEST_DATA_DIR) + "/materials/" + name;
}

// The InputError that loading path throws; fails the test when nothing is thrown.
InputError load_error(const std::string& path) {
  try {
    load_preset_table(path);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no InputError loading " << path;
  return InputError("", "");
}

TEST(PresetTable, ShippedTableHasTheTwentyFourPresetsInTableOrder) {
  const std::vector<Preset>& table = preset_table();
  ASSERT_EQ(table.size(), 24u);
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_EQ(table[i].name, table_shininess[i].name) << "row " << i;
  }
}

TEST(PresetTable, EveryShininessIsTheTableFractionTimes128) {
  const std::vector<Preset>& table = preset_table();
  ASSERT_EQ(table.size(), 24u);
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_FLOAT_EQ(table[i].shininess_raw, table_shininess[i].raw) << table[i].name;
    EXPECT_FLOAT_EQ(table[i].material.shininess, table_exponents[i]) << table[i].name;
  }
}

TEST(PresetTable, FullRowsMatchTheTable) {
  for (const FullRow& row : full_rows) {
    const Preset* preset = find_preset(row.name);
    ASSERT_NE(preset, nullptr) << row.name;
    for (int c = 0; c < 3; ++c) {
      EXPECT_FLOAT_EQ(preset->material.ambient[c], row.ambient[c]) << row.name << " ambient " << c;
      EXPECT_FLOAT_EQ(preset->material.diffuse[c], row.diffuse[c]) << row.name << " diffuse " << c;
      EXPECT_FLOAT_EQ(preset->material.specular[c], row.specular[c])
          << row.name << " specular " << c;
    }
    EXPECT_FLOAT_EQ(preset->material.shininess, row.shininess) << row.name;
  }
}

TEST(PresetTable, PresetsHaveNoEmissionAndRecordTheirName) {
  for (const Preset& preset : preset_table()) {
    EXPECT_EQ(preset.material.emission, glm::vec3(0.0f)) << preset.name;
    EXPECT_EQ(preset.material.preset, preset.name);
  }
}

TEST(PresetTable, ShippedTableIsTheAssetsCsv) {
  const std::vector<Preset> loaded =
      load_preset_table(std::string(GLOSS_ASSETS_DIR) + "/materials/opengl-vrml.csv");
  const std::vector<Preset>& shipped = preset_table();
  ASSERT_EQ(loaded.size(), shipped.size());
  for (std::size_t i = 0; i < loaded.size(); ++i) {
    EXPECT_EQ(loaded[i].material, shipped[i].material);
  }
}

TEST(PresetTable, IsLoadedOnceAndSharedAcrossThreads) {
  const std::vector<Preset>* seen[4] = {};
  std::vector<std::thread> threads;
  for (auto& slot : seen) threads.emplace_back([&slot] { slot = &preset_table(); });
  for (std::thread& thread : threads) thread.join();
  for (const auto* table : seen) EXPECT_EQ(table, &preset_table());
}

TEST(PresetTable, FindPresetReturnsNullForUnknownName) {
  EXPECT_EQ(find_preset("gld"), nullptr);
  EXPECT_EQ(find_preset("Gold"), nullptr);  // names are lowercase, compared exactly
  EXPECT_EQ(find_preset(""), nullptr);
}

TEST(PresetTable, NearestNamesOfMisspellingIncludeTheIntendedPreset) {
  const std::vector<std::string> nearest = nearest_preset_names("gld");
  ASSERT_EQ(nearest.size(), 3u);
  EXPECT_EQ(nearest[0], "gold");
  EXPECT_EQ(nearest_preset_names("blak_plastic", 1), std::vector<std::string>{"black_plastic"});
  EXPECT_EQ(nearest_preset_names("rubyy", 5).front(), "ruby");
}

TEST(PresetTable, RowWithMissingFieldNamesFileAndLine) {
  const std::string path = data_file("presets_short_row.csv");
  const InputError error = load_error(path);
  EXPECT_EQ(error.file(), path);
  EXPECT_EQ(error.line(), 4);
  EXPECT_NE(std::string(error.what()).find(path + ":4"), std::string::npos) << error.what();
  EXPECT_NE(error.message().find("got 10"), std::string::npos) << error.message();
}

TEST(PresetTable, NonNumericValueNamesLineAndColumn) {
  const InputError error = load_error(data_file("presets_bad_number.csv"));
  EXPECT_EQ(error.line(), 3);
  EXPECT_EQ(error.column(), 12);
  EXPECT_NE(error.message().find("'abc'"), std::string::npos) << error.message();
}

TEST(PresetTable, MissingHeaderIsAnError) {
  const InputError error = load_error(data_file("presets_no_header.csv"));
  EXPECT_EQ(error.line(), 2);
  EXPECT_NE(error.message().find("header"), std::string::npos) << error.message();
}

TEST(PresetTable, MissingFileIsAnInputErrorNamingThePath) {
  const std::string path = data_file("no_such_table.csv");
  const InputError error = load_error(path);
  EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
}

TEST(PresetTable, AcceptsCrlfLineEndsAndBlankLines) {
  ScratchFolder folder;
  const std::string path = folder.file("crlf.csv");
  std::ofstream(path, std::ios::binary)
      << "# note\r\n\r\nname,ar,ag,ab,dr,dg,db,sr,sg,sb,shininess_raw\r\n"
      << "matte,0.1,0.2,0.3,0.4,0.5,0.6,0,0,0,0.5\r\n\r\n";
  const std::vector<Preset> presets = load_preset_table(path);
  ASSERT_EQ(presets.size(), 1u);
  EXPECT_EQ(presets[0].name, "matte");
  EXPECT_EQ(presets[0].material.diffuse, glm::vec3(0.4f, 0.5f, 0.6f));
  EXPECT_EQ(presets[0].material.shininess, 64.0f);
}

TEST(PresetTable, NegativeValueAndDuplicateNameAreErrors) {
  ScratchFolder folder;
  const std::string header = "name,ar,ag,ab,dr,dg,db,sr,sg,sb,shininess_raw\n";
  const std::string negative = folder.file("negative.csv");
  std::ofstream(negative) << header << "m,0,0,0,-0.5,0,0,0,0,0,0.5\n";
  EXPECT_EQ(load_error(negative).line(), 2);
  const std::string duplicate = folder.file("duplicate.csv");
  std::ofstream(duplicate) << header << "m,0,0,0,0,0,0,0,0,0,0.5\nm,0,0,0,0,0,0,0,0,0,0.5\n";
  EXPECT_EQ(load_error(duplicate).line(), 3);
}

// Sets GLOSS_ASSETS for one test and restores the previous value (ctest sets it).
class AssetsVariable {
 public:
  explicit AssetsVariable(const char* value) {
    const char* old = std::getenv("GLOSS_ASSETS");
    m_had_old = old != nullptr;
    if (m_had_old) m_old = old;
    ::setenv("GLOSS_ASSETS", value, 1);
  }
  ~AssetsVariable() {
    if (m_had_old) {
      ::setenv("GLOSS_ASSETS", m_old.c_str(), 1);
    } else {
      ::unsetenv("GLOSS_ASSETS");
    }
  }

 private:
  bool m_had_old = false;
  std::string m_old;
};

TEST(PresetAssets, EnvironmentVariableChoosesTheAssetFolder) {
  const AssetsVariable variable("/opt/elsewhere/assets");
  EXPECT_EQ(asset_dir(), "/opt/elsewhere/assets");
  EXPECT_EQ(asset_path("materials/opengl-vrml.csv"),
            "/opt/elsewhere/assets/materials/opengl-vrml.csv");
}

TEST(PresetAssets, EmptyEnvironmentVariableFallsBackToTheSourceTree) {
  const AssetsVariable variable("");
  EXPECT_EQ(asset_dir(), GLOSS_ASSETS_DIR);
}

}  // namespace
}  // namespace gloss

#include "io/json/material_json.h"
#include "io/material/material_io.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "base/error.h"
#include "io/material/preset_table.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

using nlohmann::json;

std::string data_file(const std::string& name) {
  return std::string(GLOSS_TEST_DATA_DIR) + "/materials/" + name;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The InputError f() throws; fails the test when nothing is thrown.
template <class F>
InputError input_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("", "");
}

InputError json_error(const json& value) {
  return input_error_of([&] { material_from_json(value, "scene.json", "materials.m"); });
}

// Floats that do not print short: thirds, tenths, denormal-adjacent and large values.
std::vector<NamedMaterial> awkward_materials() {
  Material a;
  a.ambient = glm::vec3(0.1f, 1.0f / 3.0f, 2.0f / 3.0f);
  a.diffuse = glm::vec3(0.7f, 1e-7f, 123456.789f);
  a.specular = glm::vec3(0.0f, 0.3f, 0.999999f);
  a.emission = glm::vec3(3.0e-38f, 5.0f, 0.2f);
  a.shininess = 1.0e6f;
  Material b = find_preset("gold")->material;
  b.shininess = 12.345678f;
  Material c;  // defaults
  c.shininess = 0.0f;
  return {{"awkward", a}, {"gold_tweaked", b}, {"plain", c}};
}

TEST(MaterialIo, ToJsonWritesAllFiveFieldsAndThePresetWhenSet) {
  const json custom = material_to_json(Material{});
  EXPECT_EQ(custom.size(), 5u);
  EXPECT_FALSE(custom.contains("preset"));
  EXPECT_EQ(custom["ambient"], json::parse("[0.2, 0.2, 0.2]"));
  EXPECT_EQ(custom["shininess"], json(32.0));

  const json gold = material_to_json(find_preset("gold")->material);
  EXPECT_EQ(gold.size(), 6u);
  EXPECT_EQ(gold["preset"], "gold");
  for (const char* key : {"ambient", "diffuse", "specular", "emission", "shininess"}) {
    EXPECT_TRUE(gold.contains(key)) << key;
  }
}

TEST(MaterialIo, ToJsonPrintsTheShortestTextThatReadsBackExactly) {
  // Table values print as typed in the table, not as their float's long double expansion.
  const std::string text = material_to_json(find_preset("gold")->material).dump();
  EXPECT_NE(text.find("[0.75164,0.60648,0.22648]"), std::string::npos) << text;
  EXPECT_NE(text.find("51.2"), std::string::npos) << text;
}

TEST(MaterialIo, JsonValueRoundTripIsExact) {
  for (const auto& [name, material] : awkward_materials()) {
    const json value = json::parse(material_to_json(material).dump());
    EXPECT_EQ(material_from_json(value, "x.json", name), material) << name;
  }
}

TEST(MaterialIo, JsonFileRoundTripIsExactAndKeepsOrder) {
  ScratchFolder folder;
  const std::string path = folder.file("library.json");
  const std::vector<NamedMaterial> materials = awkward_materials();
  save_materials_json(path, materials);
  EXPECT_EQ(load_materials_json(path), materials);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"library.json"});
}

TEST(MaterialIo, PresetFieldsCanBeOverridden) {
  const Material m =
      material_from_json(json::parse(R"({"preset": "gold", "shininess": 12})"), "f", "m");
  const Material& gold = find_preset("gold")->material;
  EXPECT_EQ(m.diffuse, gold.diffuse);
  EXPECT_EQ(m.specular, gold.specular);
  EXPECT_EQ(m.shininess, 12.0f);
  EXPECT_EQ(m.preset, "gold");
}

TEST(MaterialIo, MissingExplicitFieldsTakeMaterialDefaults) {
  const Material m = material_from_json(json::parse(R"({"diffuse": [0.6, 0.1, 0.1]})"), "f", "m");
  EXPECT_EQ(m.diffuse, glm::vec3(0.6f, 0.1f, 0.1f));
  const Material defaults;
  EXPECT_EQ(m.ambient, defaults.ambient);
  EXPECT_EQ(m.specular, defaults.specular);
  EXPECT_EQ(m.emission, defaults.emission);
  EXPECT_EQ(m.shininess, defaults.shininess);
  EXPECT_TRUE(m.preset.empty());
}

// The physical reference block (docs/scene-format.md): read, written only when present, exact.
TEST(MaterialIo, ReferenceBlockRoundTrips) {
  const Material m = material_from_json(
      json::parse(R"({"preset": "gold", "reference": {"kind": "gold", "roughness": 0.2}})"), "f",
      "m");
  ASSERT_TRUE(m.reference.has_value());
  EXPECT_EQ(m.reference->kind, ReferenceKind::gold);
  EXPECT_EQ(m.reference->roughness, 0.2f);
  EXPECT_EQ(m.reference->base, PhysicalReference{}.base);  // the default, unused by a metal
  EXPECT_EQ(m.preset, "gold");
  const json written = material_to_json(m);
  EXPECT_EQ(written["reference"]["kind"], "gold");
  EXPECT_FALSE(written["reference"].contains("base"));  // a metal's unused default
  EXPECT_EQ(material_from_json(json::parse(written.dump()), "f", "m"), m);

  Material plastic;
  PhysicalReference red;
  red.kind = ReferenceKind::dielectric;
  red.base = glm::vec3(0.6f, 0.05f, 0.05f);
  red.roughness = 1.0f / 3.0f;
  plastic.reference = red;
  EXPECT_EQ(material_from_json(json::parse(material_to_json(plastic).dump()), "f", "m"), plastic);
  EXPECT_NE(plastic, Material{});  // the reference is part of a material's identity
}

TEST(MaterialIo, ReferenceBlockErrorsNameTheField) {
  EXPECT_EQ(json_error(json::parse(R"({"reference": {"roughness": 0.2}})")).field(),
            "materials.m.reference.kind");
  const InputError kind = json_error(json::parse(R"({"reference": {"kind": "gld"}})"));
  EXPECT_EQ(kind.field(), "materials.m.reference.kind");
  const InputError zero =
      json_error(json::parse(R"({"reference": {"kind": "silver", "roughness": 0}})"));
  EXPECT_EQ(zero.field(), "materials.m.reference.roughness");
  const InputError base =
      json_error(json::parse(R"({"reference": {"kind": "dielectric", "base": [1.5, 0, 0]}})"));
  EXPECT_EQ(base.field(), "materials.m.reference.base[0]");
  const InputError key =
      json_error(json::parse(R"({"reference": {"kind": "gold", "rougness": 0.5}})"));
  EXPECT_EQ(key.message(), "unknown key 'rougness' (did you mean 'roughness'?)");
  EXPECT_EQ(json_error(json::parse(R"({"reference": "gold"})")).field(), "materials.m.reference");
}

TEST(MaterialIo, LoadsALibraryFileInFileOrder) {
  const std::vector<NamedMaterial> materials = load_materials_json(data_file("library.json"));
  ASSERT_EQ(materials.size(), 3u);
  EXPECT_EQ(materials[0].first, "zinc");
  EXPECT_EQ(materials[0].second.diffuse, glm::vec3(0.5f, 0.5f, 0.55f));
  EXPECT_EQ(materials[0].second.shininess, 80.0f);
  EXPECT_EQ(materials[1].first, "soft_gold");
  EXPECT_EQ(materials[1].second.diffuse, glm::vec3(0.75164f, 0.60648f, 0.22648f));
  EXPECT_EQ(materials[1].second.shininess, 12.0f);
  EXPECT_EQ(materials[2].first, "lamp");
  EXPECT_EQ(materials[2].second.emission, glm::vec3(2.0f, 1.5f, 1.0f));
}

TEST(MaterialIo, UnknownKeyNamesTheFieldAndTheNearestKnownKey) {
  const InputError error = json_error(json::parse(R"({"difuse": [1, 1, 1]})"));
  EXPECT_EQ(error.file(), "scene.json");
  EXPECT_EQ(error.field(), "materials.m.difuse");
  EXPECT_EQ(error.message(), "unknown key 'difuse' (did you mean 'diffuse'?)");
  EXPECT_EQ(std::string(error.what()),
            "scene.json: materials.m.difuse: unknown key 'difuse' (did you mean 'diffuse'?)");
}

TEST(MaterialIo, WrongComponentCountIsReported) {
  const InputError error = json_error(json::parse(R"({"diffuse": [1, 1]})"));
  EXPECT_EQ(error.field(), "materials.m.diffuse");
  EXPECT_EQ(error.message(), "expected 3 numbers, got 2 values");
}

TEST(MaterialIo, WrongTypesAreReported) {
  EXPECT_EQ(json_error(json::parse(R"({"diffuse": "red"})")).field(), "materials.m.diffuse");
  EXPECT_EQ(json_error(json::parse(R"({"diffuse": [1, "x", 1]})")).field(),
            "materials.m.diffuse[1]");
  EXPECT_EQ(json_error(json::parse(R"({"shininess": [1]})")).field(), "materials.m.shininess");
  EXPECT_EQ(json_error(json::parse(R"({"preset": 3})")).field(), "materials.m.preset");
  EXPECT_EQ(json_error(json::parse("[1, 2, 3]")).field(), "materials.m");
}

TEST(MaterialIo, NegativeValuesAreRejected) {
  const InputError colour = json_error(json::parse(R"({"specular": [1, -0.5, 1]})"));
  EXPECT_EQ(colour.field(), "materials.m.specular[1]");
  EXPECT_EQ(colour.message(), "must be >= 0, got -0.5");
  EXPECT_EQ(json_error(json::parse(R"({"shininess": -1})")).field(), "materials.m.shininess");
}

TEST(MaterialIo, NonFiniteValuesAreRejected) {
  json nan_value = json::parse(R"({"ambient": [0, 0, 0]})");
  nan_value["ambient"][2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(json_error(nan_value).field(), "materials.m.ambient[2]");
  // 1e39 is a finite double but overflows a float.
  EXPECT_EQ(json_error(json::parse(R"({"shininess": 1e39})")).field(), "materials.m.shininess");
}

TEST(MaterialIo, UnknownPresetNamesTheNearestPresets) {
  const InputError error = json_error(json::parse(R"({"preset": "gld"})"));
  EXPECT_EQ(error.field(), "materials.m.preset");
  EXPECT_EQ(error.message().rfind("unknown preset 'gld' (nearest: gold, ", 0), 0u)
      << error.message();
}

TEST(MaterialIo, JsonSyntaxErrorGivesFileLineAndColumn) {
  // Line 3 is `    "red": {"diffuse": [0.6, 0.1, 0.1],}`: the '}' after the trailing comma
  // is column 40.
  const std::string path = data_file("syntax_error.json");
  const InputError error = input_error_of([&] { load_materials_json(path); });
  EXPECT_EQ(error.line(), 3);
  EXPECT_EQ(error.column(), 40);
  EXPECT_EQ(std::string(error.what()).rfind(path + ":3:40: ", 0), 0u) << error.what();
}

TEST(MaterialIo, JsonFileErrorsNameTheFileAndField) {
  const std::string path = data_file("unknown_key.json");
  const InputError error = input_error_of([&] { load_materials_json(path); });
  EXPECT_EQ(error.file(), path);
  EXPECT_EQ(error.field(), "materials.red.difuse");

  ScratchFolder folder;
  const std::string top = folder.file("top.json");
  std::ofstream(top) << R"({"material": {}})";
  EXPECT_EQ(input_error_of([&] { load_materials_json(top); }).message(),
            "unknown key 'material' (did you mean 'materials'?)");
  const std::string missing = folder.file("missing.json");
  EXPECT_NE(std::string(input_error_of([&] { load_materials_json(missing); }).what()).find(missing),
            std::string::npos);
}

TEST(MaterialIo, SaveMtlWritesPhongStatementsWithACommentHeader) {
  ScratchFolder folder;
  const std::string path = folder.file("gold.mtl");
  save_mtl(path, {{"gold", find_preset("gold")->material}});
  const std::string text = read_file(path);
  EXPECT_EQ(text.rfind("# ", 0), 0u);
  for (const char* line :
       {"\nnewmtl gold\n", "\nKa 0.24725 0.1995 0.0745\n", "\nKd 0.75164 0.60648 0.22648\n",
        "\nKs 0.628281 0.555802 0.366065\n", "\nKe 0 0 0\n", "\nNs 51.2\n", "\nillum 2\n"}) {
    EXPECT_NE(text.find(line), std::string::npos) << line << " missing from\n" << text;
  }
}

TEST(MaterialIo, MtlRoundTripIsExact) {
  ScratchFolder folder;
  const std::string path = folder.file("library.mtl");
  std::vector<NamedMaterial> materials = awkward_materials();
  save_mtl(path, materials);
  // MTL has no place for the preset a material came from.
  for (auto& named : materials) named.second.preset.clear();
  EXPECT_EQ(load_mtl(path), materials);
}

TEST(MaterialIo, LoadMtlReadsPhongLinesAndIgnoresOtherStatements) {
  const std::vector<NamedMaterial> materials = load_mtl(data_file("exported.mtl"));
  ASSERT_EQ(materials.size(), 2u);
  const Material& metal = materials[0].second;
  EXPECT_EQ(materials[0].first, "Brushed Metal");
  EXPECT_EQ(metal.ambient, glm::vec3(1.0f));
  EXPECT_EQ(metal.diffuse, glm::vec3(0.8f));
  EXPECT_EQ(metal.specular, glm::vec3(0.5f));
  EXPECT_EQ(metal.emission, glm::vec3(0.0f));
  EXPECT_EQ(metal.shininess, 250.0f);
  const Material& red = materials[1].second;
  EXPECT_EQ(materials[1].first, "red");
  EXPECT_EQ(red.diffuse, glm::vec3(0.6f, 0.1f, 0.1f));
  EXPECT_EQ(red.ambient, glm::vec3(0.05f));  // one value stands for all three channels
  EXPECT_EQ(red.specular, Material{}.specular);
  EXPECT_EQ(red.shininess, Material{}.shininess);
}

TEST(MaterialIo, LoadMtlAcceptsCrlfAndAnyKeywordCase) {
  const std::vector<NamedMaterial> materials = load_mtl(data_file("crlf_upper.mtl"));
  ASSERT_EQ(materials.size(), 1u);
  EXPECT_EQ(materials[0].first, "glow");
  EXPECT_EQ(materials[0].second.emission, glm::vec3(1.0f, 0.5f, 0.0f));
  EXPECT_EQ(materials[0].second.diffuse, glm::vec3(0.25f));
}

TEST(MaterialIo, MalformedMtlLinesNameFileAndLine) {
  const std::string kd_path = data_file("bad_kd.mtl");
  const InputError kd = input_error_of([&] { load_mtl(kd_path); });
  EXPECT_EQ(kd.line(), 5);
  EXPECT_NE(std::string(kd.what()).find(kd_path + ":5"), std::string::npos) << kd.what();
  const InputError ns = input_error_of([&] { load_mtl(data_file("bad_ns.mtl")); });
  EXPECT_EQ(ns.line(), 3);
  EXPECT_NE(ns.message().find("'shiny'"), std::string::npos) << ns.message();

  ScratchFolder folder;
  const std::string orphan = folder.file("orphan.mtl");
  std::ofstream(orphan) << "# no newmtl yet\nKd 1 1 1\n";
  EXPECT_EQ(input_error_of([&] { load_mtl(orphan); }).line(), 2);
  const std::string negative = folder.file("negative.mtl");
  std::ofstream(negative) << "newmtl a\nKs 1 -1 1\n";
  EXPECT_EQ(input_error_of([&] { load_mtl(negative); }).line(), 2);
}

TEST(MaterialIo, SavingIntoAMissingFolderFailsAndLeavesNoFile) {
  ScratchFolder folder;
  const std::string json_path = folder.file("missing/library.json");
  const std::string mtl_path = folder.file("missing/library.mtl");
  EXPECT_THROW(save_materials_json(json_path, awkward_materials()), RuntimeFailure);
  EXPECT_THROW(save_mtl(mtl_path, awkward_materials()), RuntimeFailure);
  EXPECT_TRUE(folder.entries().empty());
}

TEST(MaterialIo, DuplicateNamesCannotBeSaved) {
  ScratchFolder folder;
  const std::vector<NamedMaterial> twice = {{"a", Material{}}, {"a", Material{}}};
  EXPECT_THROW(save_materials_json(folder.file("twice.json"), twice), RuntimeFailure);
  EXPECT_THROW(save_mtl(folder.file("twice.mtl"), twice), RuntimeFailure);
  EXPECT_TRUE(folder.entries().empty());
}

// fuzz/fuzz_mtl found a name the reader took and save_mtl refused: a carriage return inside the
// line (fuzz/corpus/mtl/name_with_inner_cr.mtl). It is refused where it is read, with its line.
TEST(MaterialIo, AMtlNameWithACarriageReturnInsideIsRefusedWithItsLine) {
  ScratchFolder folder;
  const std::string path = folder.file("cr.mtl");
  std::ofstream(path, std::ios::binary) << "newmtl ok\nKd 1 1 1\nnewmtl bad\r.5\nKd 0.8 0.7 0.5\n";
  try {
    load_mtl(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.message(), "material name contains a carriage return");
  }
}

}  // namespace
}  // namespace gloss

// gloss-cli fit and render --physical as a user runs them (GLOSS_CLI_PATH): the constants and
// residuals printed, the JSON, the materials file it adds to, one error line and exit 2 for bad
// input, nothing written by a failure.
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/image/image_io.h"
#include "io/material/material_io.h"
#include "support/cli_run.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

class FitCli : public ::testing::Test {
 protected:
  CliRun run(const std::string& args) { return run_cli(args, logs, outputs.path().string()); }
  void expect_bad_input(const std::string& args, const std::string& names) {
    const CliRun r = run("fit " + args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    const std::vector<std::string> lines = lines_of(r.err);
    ASSERT_EQ(lines.size(), 1u) << r.err;
    EXPECT_EQ(lines[0].rfind("error: fit: ", 0), 0u) << lines[0];
    EXPECT_NE(lines[0].find(names), std::string::npos) << lines[0];
    EXPECT_TRUE(outputs.entries().empty());
  }
  // The line that starts with key, its words after the key.
  static std::vector<double> numbers_after(const std::string& out, const std::string& key) {
    for (const std::string& line : lines_of(out)) {
      if (line.rfind(key + " ", 0) != 0) continue;
      std::istringstream in(line.substr(key.size()));
      std::vector<double> values;
      for (double x; in >> x;) values.push_back(x);
      return values;
    }
    ADD_FAILURE() << "no line '" << key << "' in " << out;
    return {};
  }
  ScratchFolder outputs, logs;
};

// The issue's own example: gold at roughness 0.2 gives a Phong gold, its residuals, and names
// the source of the measured values.
TEST_F(FitCli, GoldPrintsConstantsResidualsAndTheSource) {
  const CliRun r = run("fit --reference gold --roughness 0.2 --json fit.json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("Real-Time Rendering, 4th ed., Table 9.2"), std::string::npos) << r.out;
  EXPECT_EQ(numbers_after(r.out, "diffuse").size(), 3u);
  const std::vector<double> ks = numbers_after(r.out, "specular");
  ASSERT_EQ(ks.size(), 3u);
  // Gold reflects red most and blue least (F0 1, 0.782, 0.344).
  EXPECT_GT(ks[0], ks[1]);
  EXPECT_GT(ks[1], ks[2]);
  EXPECT_EQ(numbers_after(r.out, "shininess").size(), 1u);
  EXPECT_NE(r.out.find("residual l2 "), std::string::npos);
  const nlohmann::json j = nlohmann::json::parse(read_all(outputs.file("fit.json")));
  EXPECT_EQ(j["reference"]["kind"], "gold");
  EXPECT_EQ(j["reference"]["roughness"], 0.2);
  EXPECT_EQ(j["reference"]["f0_source"], "Real-Time Rendering, 4th ed., Table 9.2");
  // The printed constants are the JSON's to 6 significant digits.
  EXPECT_NEAR(j["specular"][0].get<double>(), ks[0], 1e-5 * ks[0]);
  EXPECT_GT(j["residual"]["l2"].get<double>(), 0.0);
  EXPECT_GT(j["residual"]["lightness"].get<double>(), 0.0);
  EXPECT_EQ(j["model"], "phong");
}

// Blinn-Phong, energy normalised, a dielectric with its base colour, the lightness metric.
TEST_F(FitCli, DielectricBlinnPhongNormalised) {
  const CliRun r =
      run("fit --reference dielectric --base 0.6,0.1,0.1 --roughness 0.4 --model blinn-phong "
          "--energy-normalize --metric lightness");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("fit blinn-phong to dielectric base 0.6 0.1 0.1"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("energy normalisation on; minimising lightness"), std::string::npos);
  const std::vector<double> kd = numbers_after(r.out, "diffuse");
  ASSERT_EQ(kd.size(), 3u);
  EXPECT_GT(kd[0], kd[1]);  // the red base shows in the diffuse
}

// Model to model: the best Blinn-Phong lobe for the gold preset, with the 4x rule beside it.
TEST_F(FitCli, PresetToTheOtherModelBesideTheFourTimesRule) {
  const CliRun r = run("fit --preset gold --model blinn-phong");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("4x rule (blinn-phong"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("alpha 204.8"), std::string::npos) << r.out;  // 51.2 x 4
}

// --add-to writes a materials file gloss reads back, with the reference block.
TEST_F(FitCli, AddsTheFittedMaterialToAMaterialsFile) {
  ASSERT_EQ(run("fit --reference copper --roughness 0.3 --add-to m.json --name copper_r03").status,
            0);
  ASSERT_EQ(run("fit --reference silver --roughness 0.1 --add-to m.json --name silver_r01").status,
            0);
  const std::vector<NamedMaterial> m = load_materials_json(outputs.file("m.json"));
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].first, "copper_r03");
  ASSERT_TRUE(m[0].second.reference.has_value());
  EXPECT_EQ(m[0].second.reference->kind, ReferenceKind::copper);
  EXPECT_EQ(m[0].second.reference->roughness, 0.3f);
  EXPECT_EQ(m[1].first, "silver_r01");
  // Fitting the same name again replaces it.
  ASSERT_EQ(run("fit --reference copper --roughness 0.5 --add-to m.json --name copper_r03").status,
            0);
  const std::vector<NamedMaterial> again = load_materials_json(outputs.file("m.json"));
  ASSERT_EQ(again.size(), 2u);
  EXPECT_EQ(again[0].second.reference->roughness, 0.5f);
}

TEST_F(FitCli, BadInputIsOneErrorLineAndExitTwo) {
  expect_bad_input("--reference gld --roughness 0.2",
                   "unknown reference 'gld' (did you mean 'gold'?)");
  expect_bad_input("--reference gold", "--roughness");
  expect_bad_input("--reference gold --roughness 0", "--roughness: must be > 0 and <= 1, got 0");
  expect_bad_input("--reference gold --roughness 1.5", "--roughness");
  expect_bad_input("--reference gold --roughness 0.2 --base 1,0,0", "only a dielectric");
  expect_bad_input("--reference dielectric --roughness 0.2 --base 1,x,0", "--base");
  expect_bad_input("--reference dielectric --roughness 0.2 --base 2,0,0", "--base");
  expect_bad_input("--reference gold --roughness 0.2 --model phon", "did you mean 'phong'");
  expect_bad_input("--reference gold --roughness 0.2 --metric l3", "--metric");
  expect_bad_input("--reference gold --roughness 0.2 --max-angle 95", "--max-angle");
  expect_bad_input("--reference gold --roughness 0.2 --max-angle 1", "from 10 to 90 degrees");
  expect_bad_input("--preset gol", "unknown preset 'gol'");
  expect_bad_input("", "give --reference");
  expect_bad_input("--reference gold --roughness 0.2 --add-to m.json", "--name");
}

// render --physical: a material's reference shaded by it; the same scene without the flag is
// Phong (the images differ), and --precision float is refused with it.
TEST_F(FitCli, RenderPhysical) {
  ScratchFolder inputs;
  std::ofstream(inputs.file("s.json")) << R"({
    "camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y": 40},
    "lights": [{"position": [2, 3, 4]}],
    "materials": {"m": {"preset": "gold", "reference": {"kind": "gold", "roughness": 0.3}}},
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}],
    "render": {"width": 40, "height": 30}
  })";
  const std::string scene = "'" + inputs.file("s.json") + "'";
  const CliRun r = run("render " + scene + " --physical --pfm ref.pfm");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("physical reference"), std::string::npos) << r.out;
  ASSERT_EQ(run("render " + scene + " --pfm phong.pfm").status, 0);
  EXPECT_NE(read_pfm(outputs.file("ref.pfm")).pixels, read_pfm(outputs.file("phong.pfm")).pixels);
  const CliRun bad = run("render " + scene + " --physical --precision float -o x.png");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--physical"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace gloss

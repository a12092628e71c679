// gloss-cli export-gltf as a user runs it (GLOSS_CLI_PATH) on the default scene: each material's
// three conversions (glTF fit, three.js fit, Phong -> glTF -> Phong) printed with the residual in
// both metrics the spec has the fit report (Ngan 2005's cosine-weighted l2, relative and
// absolute, and CIE L*), the same residuals in --json, and the three.js file in three.js's JSON
// Object format.
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_run.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

using nlohmann::json;

json read_json(const std::string& path) {
  std::ifstream in(path);
  return json::parse(in);
}

// The residual printed at the end of a conversion line: "residual P % (l2 A, L* B)".
struct Printed {
  double percent = -1.0, l2 = -1.0, lightness = -1.0;
};
Printed printed_residual(const std::string& line) {
  Printed p;
  const std::size_t at = line.rfind("residual ");
  if (at == std::string::npos) return p;
  std::string percent_sign, l2_word, l_word;
  std::istringstream in(line.substr(at + 9));
  char comma = 0;
  in >> p.percent >> percent_sign >> l2_word >> p.l2 >> comma >> l_word >> p.lightness;
  if (percent_sign != "%" || l2_word != "(l2" || comma != ',' || l_word != "L*") p = Printed{};
  return p;
}

TEST(ExportCli, EveryConversionPrintsAndWritesBothMetrics) {
  ScratchFolder outputs, logs;
  const CliRun r = run_cli(std::string("export-gltf '") + GLOSS_SCENES_DIR +
                               "/spheres.json' out.glb --json conv.json --threejs three.json",
                           logs, outputs.path().string());
  ASSERT_EQ(r.status, 0) << r.err;
  const json conversions = read_json(outputs.file("conv.json"));
  ASSERT_EQ(conversions["materials"].size(), 3u);
  const std::vector<std::string> lines = lines_of(r.out);
  for (const json& m : conversions["materials"]) {
    const std::string name = m["name"];
    SCOPED_TRACE(name);
    const std::pair<const char*, const char*> kinds[] = {
        {": glTF base ", "gltf"},
        {": three.js color ", "threejs_phong"},
        {": Phong -> glTF -> Phong ", "round_trip"}};
    for (const auto& [prefix, key] : kinds) {
      const json& residual = m[key]["residual"];
      ASSERT_TRUE(residual.contains("l2_relative") && residual.contains("lightness")) << key;
      bool found = false;
      for (const std::string& line : lines) {
        if (line.rfind(name + prefix, 0) != 0) continue;
        found = true;
        const Printed p = printed_residual(line);
        // Printed with 3 significant digits: within half a unit of the last one.
        const double percent = 100.0 * residual["l2_relative"].get<double>();
        EXPECT_NEAR(p.percent, percent, 0.005 * percent + 1e-9) << line;
        EXPECT_NEAR(p.l2, residual["l2"].get<double>(), 0.005 * p.l2 + 1e-9) << line;
        EXPECT_NEAR(p.lightness, residual["lightness"].get<double>(), 0.005 * p.lightness + 1e-9)
            << line;
      }
      EXPECT_TRUE(found) << name << prefix << "\n" << r.out;
    }
  }
  EXPECT_EQ(read_json(outputs.file("three.json"))["metadata"]["type"], "Object");
}

}  // namespace
}  // namespace gloss

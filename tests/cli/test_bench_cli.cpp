// gloss-cli bench's scaling rows end to end (GLOSS_CLI_PATH): the process that measures one row
// (`--scaling-row`, what `--scaling` spawns per row) writes its point as the JSON object that
// `bench --json` lists under "scaling"; a malformed row is bad input (exit 2). The environment's
// section (`--environment`) at a tiny size: its figures and the progressive path's curve reach
// the target; a missing map is bad input naming the file.
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/image/exr_writer.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

int run_bench(const std::string& args, const ScratchFolder& folder) {
  const std::string command = "cd '" + folder.path().string() + "' && '" + GLOSS_CLI_PATH +
                              "' bench " + args + " >out.txt 2>err.txt";
  const int raw = std::system(command.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(BenchCli, AScalingRowWritesItsPointAsJson) {
  ScratchFolder folder;
  ASSERT_EQ(run_bench("--scaling-row 4,0,48,27 --runs 1 --json row.json", folder), 0)
      << slurp(folder.file("err.txt"));
  const nlohmann::json row = nlohmann::json::parse(slurp(folder.file("row.json")));
  EXPECT_EQ(row.at("lights"), 4);
  EXPECT_EQ(row.at("width"), 48);
  EXPECT_EQ(row.at("height"), 27);
  EXPECT_GT(row.at("triangles").get<long long>(), 10);  // the box's walls and the teapot
  EXPECT_GT(row.at("retrace_ms").get<double>(), 0.0);
  EXPECT_GT(row.at("ratio").get<double>(), 0.0);
  EXPECT_FALSE(row.contains("skipped"));
}

TEST(BenchCli, AMalformedScalingRowIsBadInput) {
  ScratchFolder folder;
  EXPECT_EQ(run_bench("--scaling-row 4,0 --json row.json", folder), 2);
  EXPECT_NE(slurp(folder.file("err.txt")).find("--scaling-row"), std::string::npos);
}

TEST(BenchCli, TheEnvironmentSectionReachesItsTargetAndReportsItsCurve) {
  ScratchFolder folder;
  // A small studio of its own (the shipped 1024 x 512 map's quadrature tree alone takes
  // seconds): a grey room lit by one box of radiance 40 above and to the left.
  Image map(128, 64, glm::vec3(0.2f));
  for (int j = 10; j < 18; ++j) {
    for (int i = 40; i < 52; ++i) map.at(i, j) = glm::vec3(40.0f);
  }
  write_exr(folder.file("box.exr"), map);
  const std::string spheres = std::string(GLOSS_ASSETS_DIR) + "/scenes/spheres.json";
  ASSERT_EQ(run_bench("'" + spheres +
                          "' --environment box.exr --environment-only --width 64 --height 36 "
                          "--runs 1 --env-accuracy-divisor 1 --json env.json",
                      folder),
            0)
      << slurp(folder.file("err.txt"));
  const nlohmann::json env = nlohmann::json::parse(slurp(folder.file("env.json")));
  EXPECT_EQ(env.at("map_width"), 128);
  EXPECT_EQ(env.at("accuracy_width"), 64);
  EXPECT_GT(env.at("fast_ratio").get<double>(), 0.0);
  EXPECT_GT(env.at("reshade_ratio").get<double>(), 0.0);
  EXPECT_GT(env.at("reference_pixels").get<long long>(), 100);
  // The curve starts at the fast path (0 directions) and ends on the first frame within 1 %.
  const nlohmann::json& curve = env.at("curve");
  ASSERT_GE(curve.size(), 2u);
  EXPECT_EQ(curve.front().at("steps"), 0);
  EXPECT_EQ(curve.back().at("steps"), env.at("steps_to_target"));
  EXPECT_LE(curve.back().at("relative_rmse").get<double>(), 0.01);
  EXPECT_GT(curve[curve.size() - 2].at("relative_rmse").get<double>(), 0.01);
  EXPECT_GT(env.at("converge_ratio").get<double>(), 1.0);
}

TEST(BenchCli, AMissingEnvironmentMapIsBadInput) {
  ScratchFolder folder;
  EXPECT_EQ(run_bench("--environment no-such-map.exr --environment-only", folder), 2);
  EXPECT_NE(slurp(folder.file("err.txt")).find("no-such-map.exr"), std::string::npos);
}

}  // namespace
}  // namespace gloss

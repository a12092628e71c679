// gloss-cli bench's scaling rows end to end (GLOSS_CLI_PATH): the process that measures one row
// (`--scaling-row`, what `--scaling` spawns per row) writes its point as the JSON object that
// `bench --json` lists under "scaling"; a malformed row is bad input (exit 2).
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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

}  // namespace
}  // namespace gloss

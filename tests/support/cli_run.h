#pragma once
// Running the real gloss-cli (GLOSS_CLI_PATH) from a test: its exit status and what it printed.
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/scratch_folder.h"

namespace gloss {

struct CliRun {
  int status = -1;
  std::string out, err;
};

inline std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Runs "cd cwd && gloss-cli args"; stdout and stderr go to files in logs (never in cwd, whose
// contents the tests inspect).
inline CliRun run_cli(const std::string& args, const ScratchFolder& logs, const std::string& cwd) {
  const std::string out = logs.file("stdout.txt"), err = logs.file("stderr.txt");
  const std::string command =
      "cd '" + cwd + "' && '" + GLOSS_CLI_PATH + "' " + args + " >'" + out + "' 2>'" + err + "'";
  const int raw = std::system(command.c_str());
  CliRun run;
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  run.out = read_all(out);
  run.err = read_all(err);
  return run;
}

}  // namespace gloss

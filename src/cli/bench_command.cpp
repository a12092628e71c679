// gloss-cli bench [SCENE] [--json FILE]: the engine benchmark (bench.h), by default on the
// Cornell box with the teapot at 1280x720.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "analysis/bench.h"
#include "base/assets.h"
#include "base/atomic_file.h"
#include "cli/commands.h"
#include "io/scene/scene_loader.h"
#include "scene/isa_variant.h"

namespace gloss {

namespace {
struct BenchArgs {
  std::string scene;
  std::string json;
  BenchOptions options;
};

// Peak resident memory (MB) of `gloss-cli render` of scene at the bench's size and 1 spp, run
// as a child process so that nothing of the benchmark counts; 0 when it cannot be measured.
double plain_render_peak_rss_mb(const std::string& scene, const BenchOptions& options) {
  namespace fs = std::filesystem;
  char dir_template[] = "/tmp/gloss-bench-XXXXXX";
  if (::mkdtemp(dir_template) == nullptr) return 0;
  const std::string out = std::string(dir_template) + "/render.png";
  std::vector<std::string> words = {"gloss-cli",
                                    "render",
                                    scene,
                                    "-o",
                                    out,
                                    "--width",
                                    std::to_string(options.width),
                                    "--height",
                                    std::to_string(options.height),
                                    "--spp",
                                    "1"};
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  double mb = 0;
  if (spawned == 0) {
    int status = 0;
    rusage usage{};
    if (::wait4(pid, &status, 0, &usage) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
      mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // KiB on Linux
    }
  }
  std::error_code ec;
  fs::remove_all(dir_template, ec);
  return mb;
}

void run_bench(const BenchArgs& args) {
  const std::string path =
      args.scene.empty() ? asset_path("scenes/cornell-teapot.json") : args.scene;
  const Scene scene = load_scene(path);
  // First, while this process is small: a spawned child's peak counts the parent's pages it
  // started from.
  const double render_peak_mb = plain_render_peak_rss_mb(path, args.options);
  BenchReport report = run_benchmark(scene, args.options);
  report.peak_rss_mb = render_peak_mb;
  std::cout << format_bench_table(report);
  // Which build of the pixel code ran: native, the baseline, or a variant the loader chose.
  std::cout << "  pixel code: " << pixel_code_isa() << "\n";
  if (!args.json.empty()) {
    write_text_atomically(args.json, bench_to_json(report));
    std::cout << "wrote " << args.json << "\n";
  }
}
}  // namespace

void add_bench_command(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench", "Benchmark the engine: re-trace, re-shade, previews, threads (medians)");
  cmd->add_option("scene", args->scene, "Scene file (default: assets/scenes/cornell-teapot.json)");
  cmd->add_option("--json", args->json, "Also write the figures as JSON to FILE");
  cmd->add_option("--width", args->options.width, "Image width in pixels")
      ->check(CLI::Range(1, 16384));
  cmd->add_option("--height", args->options.height, "Image height in pixels")
      ->check(CLI::Range(1, 16384));
  cmd->add_option("--runs", args->options.runs, "Repetitions per figure")
      ->check(CLI::Range(1, 1000));
  cmd->callback([args] { run_bench(*args); });
}

}  // namespace gloss

// gloss-cli bench [SCENE] [--json FILE]: the engine benchmark (bench.h), by default on the
// Cornell box with the teapot at 1280x720.
#include <iostream>
#include <string>

#include "analysis/bench.h"
#include "base/assets.h"
#include "base/atomic_file.h"
#include "cli/commands.h"
#include "io/scene_loader.h"

namespace gloss {

namespace {
struct BenchArgs {
  std::string scene;
  std::string json;
  BenchOptions options;
};

void run_bench(const BenchArgs& args) {
  const std::string path =
      args.scene.empty() ? asset_path("scenes/cornell-teapot.json") : args.scene;
  const Scene scene = load_scene(path);
  const BenchReport report = run_benchmark(scene, args.options);
  std::cout << format_bench_table(report);
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

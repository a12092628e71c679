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
#include <optional>
#include <string>
#include <vector>

#include "analysis/bench/bench.h"
#include "analysis/bench/bench_scaling.h"
#include "base/assets.h"
#include "base/atomic_file.h"
#include "cli/commands.h"
#include "io/scene/environment_reader.h"
#include "io/scene/scene_loader.h"
#include "scene/isa_variant.h"

namespace gloss {

namespace {
struct BenchArgs {
  std::string scene;
  std::string json;
  bool scaling = false;     // --scaling: the rows of bench_scaling.h, each in its own process
  std::string scaling_row;  // hidden --scaling-row L,T,W,H: measure that row alone (the child)
  std::string environment;  // --environment FILE|NAME: the environment section with that map
  bool environment_only = false;
  BenchOptions options;
  EnvironmentBenchOptions environment_options;
};

// Runs this program with `words` as its arguments, stdout to /dev/null, and waits. Returns its
// peak resident memory (MB) when it exited 0, else -1.
double run_child(std::vector<std::string> words) {
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  rusage usage{};
  if (::wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    return -1;
  }
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // KiB on Linux
}

// A scratch folder for a child's output, removed with the object.
struct ScratchFolder {
  std::string path;
  ScratchFolder() {
    char dir_template[] = "/tmp/gloss-bench-XXXXXX";
    if (::mkdtemp(dir_template) != nullptr) path = dir_template;
  }
  ~ScratchFolder() {
    std::error_code ec;
    if (!path.empty()) std::filesystem::remove_all(path, ec);
  }
};

// Peak resident memory (MB) of `gloss-cli render` of scene at the bench's size and 1 spp, run
// as a child process so that nothing of the benchmark counts; 0 when it cannot be measured.
double plain_render_peak_rss_mb(const std::string& scene, const BenchOptions& options) {
  const ScratchFolder dir;
  if (dir.path.empty()) return 0;
  const double mb = run_child({"gloss-cli", "render", scene, "-o", dir.path + "/render.png",
                               "--width", std::to_string(options.width), "--height",
                               std::to_string(options.height), "--spp", "1"});
  return std::max(mb, 0.0);
}

// Each scaling row measured in a child process (`bench SCENE --scaling-row ...`), so the peak
// resident memory it reports is that row's alone.
std::vector<ScalingPoint> scaling_rows(const std::string& scene, const BenchOptions& options) {
  std::vector<ScalingPoint> rows;
  for (const ScalingSetup& setup : scaling_setups()) {
    std::cerr << "scaling row " << scaling_setup_text(setup) << " ...\n";
    const ScratchFolder dir;
    const std::string json = dir.path + "/row.json";
    const double mb =
        dir.path.empty()
            ? -1
            : run_child({"gloss-cli", "bench", scene, "--scaling-row", scaling_setup_text(setup),
                         "--runs", std::to_string(options.runs), "--json", json});
    ScalingPoint point;
    point.setup = setup;
    if (mb < 0) {
      point.skipped = "the row's process failed";
    } else {
      point = parse_scaling_point(read_text_file(json));
      point.peak_rss_mb = mb;
    }
    rows.push_back(point);
  }
  return rows;
}

// The scene with the map of --environment (a file, or a shipped map's name: studio, sunset,
// city) in place of its own environment, if any; intensity and rotation as the scene says.
Scene with_environment(Scene scene, const std::string& map) {
  namespace fs = std::filesystem;
  std::error_code error;
  const std::string shipped = asset_path("environments/" + map + ".exr");
  const std::string file = !fs::exists(map, error) && fs::exists(shipped, error) ? shipped : map;
  scene.environment.map = read_environment_map(file);
  scene.environment.file = file;
  return scene;
}

void run_bench(const BenchArgs& args) {
  const std::string path =
      args.scene.empty() ? asset_path("scenes/cornell-teapot.json") : args.scene;
  Scene scene = load_scene(path);
  // The environment section runs for --environment or a scene with an environment; the other
  // figures are then those of the scene without it (point lights: their baseline).
  if (!args.environment.empty()) scene = with_environment(scene, args.environment);
  std::optional<EnvironmentBenchReport> environment;
  if (scene.environment.present()) {
    EnvironmentBenchOptions options = args.environment_options;
    options.width = args.options.width;
    options.height = args.options.height;
    options.runs = args.options.runs;
    environment = run_environment_benchmark(scene, options);
    scene.environment = Environment{};
    if (args.environment_only) {
      std::cout << format_environment_bench_table(*environment);
      if (!args.json.empty()) {
        write_text_atomically(args.json, environment_bench_json(*environment) + "\n");
        std::cout << "wrote " << args.json << "\n";
      }
      return;
    }
  }
  if (!args.scaling_row.empty()) {  // a child of --scaling: one row, written as JSON
    const ScalingPoint point =
        run_scaling_row(scene, parse_scaling_setup(args.scaling_row), args.options.runs);
    write_text_atomically(args.json, scaling_point_json_text(point));
    return;
  }
  // First, while this process is small: a spawned child's peak counts the parent's pages it
  // started from.
  const double render_peak_mb = plain_render_peak_rss_mb(path, args.options);
  std::vector<ScalingPoint> scaling;
  if (args.scaling) scaling = scaling_rows(path, args.options);
  BenchReport report = run_benchmark(scene, args.options);
  report.peak_rss_mb = render_peak_mb;
  report.environment = environment;
  report.scaling = std::move(scaling);
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
  cmd->add_option("--environment", args->environment,
                  "Also measure the environment light with this map (FILE, or studio, sunset, "
                  "city): fast path, edit, progressive path to 1 % relative RMSE (minutes)");
  cmd->add_flag("--environment-only", args->environment_only,
                "Only the environment's figures (with --environment or a scene that has one)");
  cmd->add_option("--env-accuracy-divisor", args->environment_options.accuracy_divisor,
                  "The progressive path's accuracy measured at 1/N of the size (4)")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--env-reference-stride", args->environment_options.reference_stride,
                  "Its exact value on every Nth pixel both ways (2)")
      ->check(CLI::Range(1, 64));
  cmd->add_flag("--scaling", args->scaling,
                "Also time how cost grows: 1-64 lights, 10 k-10 M triangles, 720p-4K (minutes)");
  // The child process of --scaling for one row; not for users (no group: hidden from --help).
  cmd->add_option("--scaling-row", args->scaling_row)->group("");
  cmd->callback([args] { run_bench(*args); });
}

}  // namespace gloss

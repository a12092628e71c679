// gloss-cli tradeoff SCENE [--csv FILE] [--plot FILE.png] [--width N] [--height N] [--runs N]
//                   [--reference-spp N] [--base-spp N] [--quick]
// Every accuracy knob's cost (median time) and error against the double-precision reference
// (tradeoff.h), as a table on stdout, a CSV, and a plot drawn by scripts/plot_tradeoff.py with
// Debian's /usr/bin/python3 and matplotlib.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <tbb/info.h>

#include "analysis/tradeoff/tradeoff.h"
#include "base/assets.h"
#include "base/atomic_file.h"
#include "base/error.h"
#include "base/text/ascii.h"
#include "cli/commands.h"
#include "cli/scene_messages.h"
#include "io/scene/scene_loader.h"

extern char** environ;

namespace gloss {

namespace {

namespace fs = std::filesystem;

// Debian's interpreter, which has python3-matplotlib; the python3 on PATH may be another one.
constexpr const char* kPython = "/usr/bin/python3";

struct TradeoffArgs {
  std::string scene, csv, plot;
  int width = 0, height = 0, runs = 0, reference_spp = 0, base_spp = 0;
  bool quick = false;
  std::vector<std::string> knobs;
};

// $GLOSS_SCRIPTS/plot_tradeoff.py when set, else scripts/ beside the assets folder (the source
// tree, or share/gloss/ of an install).
std::string plot_script() {
  const char* dir = std::getenv("GLOSS_SCRIPTS");
  const fs::path base = dir != nullptr && *dir != '\0'
                            ? fs::path(dir)
                            : fs::path(asset_dir()).parent_path() / "scripts";
  return (base / "plot_tradeoff.py").string();
}

// Refuses, before the long measurement, an output whose folder is missing or read-only.
void check_writable(const std::string& output) {
  const fs::path folder = fs::path(output).parent_path();
  const fs::path dir = folder.empty() ? fs::path(".") : folder;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw RuntimeFailure("cannot write " + output + ": folder " + dir.string() + " does not exist");
  }
  if (::access(dir.c_str(), W_OK) != 0) {
    throw RuntimeFailure("cannot write " + output + ": folder " + dir.string() +
                         " is not writable");
  }
}

// Runs the plot script on csv_path, writing png_path; stdout discarded, stderr's last line
// reported on failure.
void run_plot_script(const std::string& script, const std::string& csv_path,
                     const std::string& png_path, const std::string& title, const std::string& base,
                     const std::string& output) {
  char log_name[] = "/tmp/gloss-plot-XXXXXX";
  const int log_fd = ::mkstemp(log_name);
  if (log_fd < 0) throw RuntimeFailure("cannot write " + output + ": no temporary file");
  ::close(log_fd);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, log_name, O_WRONLY | O_TRUNC, 0);
  std::vector<std::string> args{kPython,   script, csv_path, png_path,
                                "--title", title,  "--base", base};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, kPython, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  const bool ran = spawned == 0 && ::waitpid(pid, &status, 0) == pid;
  std::string last;
  if (std::FILE* log = std::fopen(log_name, "r")) {
    char line[512];
    while (std::fgets(line, sizeof line, log) != nullptr) {
      if (line[0] != '\n') last = line;
    }
    std::fclose(log);
  }
  std::remove(log_name);
  while (!last.empty() && (last.back() == '\n' || last.back() == ' ')) last.pop_back();
  if (!ran || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw RuntimeFailure("cannot write " + output + ": " + script + " failed" +
                         (last.empty() ? std::string() : " (" + last + ")"));
  }
}

void print_row(const TradeoffRow& r) {
  char line[256];
  const std::string marks =
      std::string(r.reference_setting ? "*" : "") + (r.base_setting ? "b" : "");
  std::snprintf(line, sizeof line, "  %-13s %-10s %-2s %11.3f %11.3g %9.2f %11.3g %9.3f\n",
                to_string(r.knob), r.setting.c_str(), marks.c_str(), r.time_ms, r.error.rmse,
                r.error.psnr_db, r.error.max_abs, r.error.pct_pixels_off);
  std::cout << line << std::flush;
}

void run_tradeoff_command(const TradeoffArgs& args) {
  std::vector<std::string> warnings, notes;
  const Scene scene = load_scene(args.scene, &warnings, &notes);
  TradeoffOptions options = args.quick ? quick_tradeoff_options() : TradeoffOptions{};
  if (args.width > 0) options.width = args.width;
  if (args.height > 0) options.height = args.height;
  if (args.runs > 0) options.runs = args.runs;
  if (args.reference_spp > 0) options.reference_spp = args.reference_spp;
  if (args.base_spp > 0) options.base_spp = args.base_spp;
  for (const std::string& name : args.knobs) {
    Knob knob;
    if (!parse_knob(name, knob)) {
      std::string names;
      for (const Knob k : tradeoff_knobs())
        names += (names.empty() ? "" : ", ") + std::string(to_string(k));
      throw CLI::ValidationError("--knobs", "no knob '" + name + "' (" + names + ")");
    }
    options.knobs.push_back(knob);
  }

  const std::string script = plot_script();
  if (!args.csv.empty()) check_writable(args.csv);
  if (!args.plot.empty()) {
    if (lower_extension(args.plot) != ".png") {
      throw InputError(args.plot, "--plot writes PNG: name the file *.png");
    }
    check_writable(args.plot);
    if (::access(kPython, X_OK) != 0) {
      throw RuntimeFailure("cannot write " + args.plot + ": " + kPython +
                           " not found (install python3-matplotlib)");
    }
    if (::access(script.c_str(), R_OK) != 0) {
      throw RuntimeFailure("cannot write " + args.plot + ": " + script + " not found");
    }
  }

  int w = 0, h = 0;
  tradeoff_image_size(scene, options, w, h);
  std::cout << "gloss tradeoff: " << args.scene << " at " << w << "x" << h << ", " << options.runs
            << " runs per row (median), " << tbb::info::default_concurrency() << " threads\n";
  for (const std::string& note : tradeoff_notes(scene, options)) std::cout << "  " << note << "\n";
  char header[256];
  std::snprintf(header, sizeof header, "  %-13s %-10s %-2s %11s %11s %9s %11s %9s\n", "knob",
                "setting", "", "time_ms", "rmse", "psnr_db", "max_abs", "pct_off");
  std::cout << header << "  (* the reference's setting of that knob, b the base's)\n" << std::flush;
  const std::vector<TradeoffRow> rows = run_tradeoff(scene, options, [](const TradeoffRow& r) {
    print_row(r);
    return true;
  });

  if (rows.empty()) {  // every knob asked for was skipped (the notes above say why)
    throw InputError(args.scene, "nothing measured: no knob asked for applies to this scene");
  }
  const std::string csv = tradeoff_to_csv(rows);
  if (!args.csv.empty()) {
    write_text_atomically(args.csv, csv);
    std::cout << "wrote " << args.csv << "\n";
  }
  if (!args.plot.empty()) {
    // The script reads the CSV from a file: the --csv output, or a temporary one.
    std::string csv_path = args.csv;
    std::string temp_csv;
    if (csv_path.empty()) {
      char name[] = "/tmp/gloss-tradeoff-XXXXXX";
      const int fd = ::mkstemp(name);
      if (fd < 0) throw RuntimeFailure("cannot write " + args.plot + ": no temporary file");
      const bool written = ::write(fd, csv.data(), csv.size()) == static_cast<ssize_t>(csv.size());
      ::close(fd);
      temp_csv = csv_path = name;
      if (!written) {
        std::remove(name);
        throw RuntimeFailure("cannot write " + args.plot + ": temporary CSV");
      }
    }
    const std::string title = fs::path(args.scene).filename().string() + ", " + std::to_string(w) +
                              "x" + std::to_string(h) + ", base " +
                              std::to_string(options.base_spp) + " spp, reference double " +
                              std::to_string(options.reference_spp) + " spp";
    // The base rows render one configuration: drawn once.
    std::string base;
    for (const TradeoffRow& r : rows) {
      if (r.base_setting)
        base += (base.empty() ? "" : ",") + std::string(to_string(r.knob)) + "=" + r.setting;
    }
    try {
      write_atomically(args.plot, [&](const std::string& temp_png) {
        run_plot_script(script, csv_path, temp_png, title, base, args.plot);
      });
    } catch (...) {
      if (!temp_csv.empty()) std::remove(temp_csv.c_str());
      throw;
    }
    if (!temp_csv.empty()) std::remove(temp_csv.c_str());
    std::cout << "wrote " << args.plot << "\n";
  }
  print_scene_messages(notes, warnings);
}

}  // namespace

void add_tradeoff_command(CLI::App& app) {
  auto args = std::make_shared<TradeoffArgs>();
  CLI::App* cmd = app.add_subcommand(
      "tradeoff", "Measure every accuracy knob: median time and error against the reference");
  cmd->add_option("scene", args->scene, "Scene file (JSON, docs/scene-format.md)")->required();
  cmd->add_option("--csv", args->csv, "Write the rows as CSV to FILE");
  cmd->add_option("--plot", args->plot, "Plot error against time to FILE.png (needs matplotlib)");
  cmd->add_option("--width", args->width, "Image width in pixels (default: the scene's)")
      ->check(CLI::Range(1, kMaxImageSide));
  cmd->add_option("--height", args->height, "Image height in pixels (default: from the aspect)")
      ->check(CLI::Range(1, kMaxImageSide));
  cmd->add_option("--runs", args->runs, "Timed renders per row (default 5)")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--reference-spp", args->reference_spp, "Reference samples per pixel (256)")
      ->check(CLI::Range(1, kMaxSpp));
  cmd->add_option("--base-spp", args->base_spp, "Samples per pixel of the non-spp rows (4)")
      ->check(CLI::Range(1, kMaxSpp));
  cmd->add_option("--knobs", args->knobs, "Only these knobs, comma-separated (default: all)")
      ->delimiter(',');
  cmd->add_flag("--quick", args->quick, "The editor's quick settings: 256 wide, 3 runs, 64 spp");
  cmd->callback([args] { run_tradeoff_command(*args); });
}

}  // namespace gloss

#include "analysis/bench/bench_environment.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>

#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <nlohmann/json.hpp>

#include "analysis/bench/bench_render.h"
#include "analysis/bench/bench_table.h"
#include "analysis/bench/paired_timing.h"
#include "analysis/bench/ray_baseline.h"
#include "analysis/image/image_metrics.h"
#include "base/timing.h"
#include "engine/environment/prefiltered_environment.h"
#include "engine/progressive_renderer.h"
#include "engine/render_context.h"
#include "reference/reference_renderer.h"

namespace gloss {

namespace {

Scene sized(const Scene& base, int width, int height) {
  Scene s = base;
  s.render.width = width;
  s.render.height = height;
  s.render.spp = 1;
  return s;
}

Scene without_environment(const Scene& scene) {
  Scene s = scene;
  s.environment = Environment{};
  return s;
}

// (a) and (b) at the full size.
void measure_edits(const Scene& scene, const EnvironmentBenchOptions& options,
                   EnvironmentBenchReport& report) {
  Scene fast = sized(scene, options.width, options.height);
  fast.render.env_samples = 0;  // the fast path alone: the first image and the drags
  const Scene point = without_environment(fast);
  const EmbreeScene embree(fast);
  SampleCache cache;
  PixelFactors factors;
  TermImages out;
  const Paired first = time_paired(
      std::max(15, 2 * options.runs),
      [&] { full_render(fast, embree, cache, factors, out, false); },
      [&] { full_render(point, embree, cache, factors, out, false); });
  report.fast_first_ms = first.f_ms;
  report.point_retrace_ms = first.g_ms;
  report.fast_ratio = first.ratio;

  // Material edit: kd of every material, recombination into the total (sky included).
  full_render(fast, embree, cache, factors, out, false);
  Scene edited = fast;
  for (Material& m : edited.materials) m.diffuse *= 0.9f;
  const RenderContext ctx = make_render_context(edited, embree);
  const std::size_t pixels = static_cast<std::size_t>(options.width) * options.height;
  const std::size_t written = pixels * sizeof(glm::vec3);
  StreamingPass stream(factors.bytes(), written);
  TermImages reshaded;
  const Paired reshade = time_paired(
      std::max(15, 3 * options.runs), [&] { combine_terms(factors, ctx, reshaded, false); },
      [&] { stream.run(); });
  report.reshade_ms = reshade.f_ms;
  report.floor_ms = reshade.g_ms;
  report.reshade_ratio = reshade.ratio;
  report.reshade_mb = static_cast<double>(factors.bytes() + written) / (1024.0 * 1024.0);
}

// Runs the engine from a camera change until a full-size frame is within the target of the
// exact image (or `stop_after` full-size frames when > 0), recording each full-size frame.
struct EngineRun {
  std::vector<EnvironmentConvergencePoint> points;
  double reached_ms = -1;  // since the change, of the frame that ended the run
};

EngineRun run_engine(const Scene& scene, const Image& exact, const std::vector<std::uint8_t>& hits,
                     double target, int stop_after) {
  ProgressiveOptions total_only;
  total_only.terms = false;
  ProgressiveRenderer engine(total_only);
  std::mutex mutex;
  std::condition_variable cv;
  EngineRun run;
  bool done = false;
  int steps = -1;  // directions per sample of the next full-size frame: 0, 16, 32, 64 ...
  engine.set_on_publish([&] {
    const auto frame = engine.latest();
    std::lock_guard<std::mutex> lock(mutex);
    if (done || frame->info.width != exact.width || frame->info.height != exact.height) return;
    steps = steps < 0 ? 0 : std::max(16, 2 * steps);
    const double error = relative_rmse(frame->images.total, exact, hits);
    run.points.push_back({steps, error, frame->info.since_change_ms});
    const bool last =
        stop_after > 0 ? static_cast<int>(run.points.size()) >= stop_after : error <= target;
    if (last || frame->info.converged) {
      if (last) run.reached_ms = frame->info.since_change_ms;
      done = true;
      cv.notify_all();
    }
  });
  engine.set_scene(scene);
  std::unique_lock<std::mutex> lock(mutex);
  cv.wait(lock, [&] { return done; });
  lock.unlock();
  engine.pause();
  engine.set_on_publish(nullptr);
  return run;
}

// Amdahl's law through the times on 1 and n threads, evaluated at 16.
double estimate_16(double t1, double tn, int n) {
  if (n <= 1 || !(t1 > 0.0)) return tn;
  const double parallel = std::clamp((1.0 - tn / t1) / (1.0 - 1.0 / n), 0.0, 1.0);
  return t1 * ((1.0 - parallel) + parallel / 16.0);
}

// (c) at the reduced size.
void measure_convergence(const Scene& scene, const EnvironmentBenchOptions& options,
                         EnvironmentBenchReport& report) {
  const int w = std::max(1, options.width / options.accuracy_divisor);
  const int h = std::max(1, options.height / options.accuracy_divisor);
  report.accuracy_width = w;
  report.accuracy_height = h;
  Scene exact_scene = sized(scene, w, h);
  exact_scene.render.shadows = false;  // the exact value is the quadrature's, not an estimate
  exact_scene.render.sampling = Sampling::uniform;
  std::vector<std::uint8_t> hits;
  ReferenceOptions reference;
  reference.spp = 1;
  reference.pixel_stride = options.reference_stride;
  reference.hits = &hits;
  const auto start = std::chrono::steady_clock::now();
  const Image exact = render_reference<double>(exact_scene, reference).total;
  report.reference_ms = ms_since(start);
  report.reference_pixels = std::count(hits.begin(), hits.end(), std::uint8_t(1));

  Scene progressive = exact_scene;
  progressive.render.env_samples = options.max_steps;
  // The camera change the engine starts from: the same view, from a fresh engine each run.
  const EngineRun all = run_engine(progressive, exact, hits, options.target, 0);
  report.curve = all.points;
  if (all.reached_ms < 0) return;  // not reached: the curve says how far it got
  report.steps_to_target = all.points.back().steps;
  report.converge_ms = all.reached_ms;

  const Scene point = without_environment(sized(scene, w, h));
  const EmbreeScene embree(point);
  SampleCache cache;
  PixelFactors factors;
  TermImages out;
  report.retrace_ms =
      time_median(options.runs, [&] { full_render(point, embree, cache, factors, out, false); });
  {
    const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    const EngineRun single =
        run_engine(progressive, exact, hits, options.target, static_cast<int>(all.points.size()));
    report.converge_ms_1 = single.reached_ms;
    report.retrace_ms_1 =
        time_median(options.runs, [&] { full_render(point, embree, cache, factors, out, false); });
  }
  report.ratio = report.converge_ms / report.retrace_ms;
  report.ratio_1 = report.converge_ms_1 / report.retrace_ms_1;
  report.ratio_16 = estimate_16(report.converge_ms_1, report.converge_ms, report.threads) /
                    estimate_16(report.retrace_ms_1, report.retrace_ms, report.threads);
}

}  // namespace

EnvironmentBenchReport run_environment_benchmark(const Scene& scene,
                                                 const EnvironmentBenchOptions& options) {
  EnvironmentBenchReport report;
  report.scene = scene.path;
  report.map = scene.environment.map->source;
  report.map_width = scene.environment.map->radiance.width;
  report.map_height = scene.environment.map->radiance.height;
  report.threads = tbb::this_task_arena::max_concurrency();
  report.target = options.target;
  PrefilterSettings settings;
  settings.texels_per_lobe = scene.render.env_resolution;
  report.prefilter_ms = time_median(std::max(1, options.runs / 2), [&] {
    const PrefilteredEnvironment levels(scene.environment.map, settings);
  });
  measure_edits(scene, options, report);
  measure_convergence(scene, options, report);
  return report;
}

std::string format_environment_bench_table(const EnvironmentBenchReport& r) {
  BenchTable table;
  table.line("environment: %s (%dx%d), %d threads (medians)\n", r.map.c_str(), r.map_width,
             r.map_height, r.threads);
  table.row("prefilter_ms", r.prefilter_ms, "ms",
            "every prefiltered level of the map, once per map");
  table.row("point_retrace_ms", r.point_retrace_ms, "ms", "point lights only, full 1-spp render");
  table.row("fast_first_ms", r.fast_first_ms, "ms",
            "with the environment's fast path, levels made");
  table.row("fast_ratio", r.fast_ratio, "", "paired; target <= 1.5");
  table.row("env_reshade_ms", r.reshade_ms, "ms", "kd edit under the environment, total image");
  table.row("env_floor_ms", r.floor_ms, "ms", "streaming the same bytes");
  table.row("env_reshade_ratio", r.reshade_ratio, "", "paired; target <= 1.5");
  table.row("env_reshade_mb", r.reshade_mb, "MB", "read and written per edit");
  table.line(
      "  progressive path to %.0f %% relative RMSE at %dx%d, shadows off (exact: "
      "reference quadrature on %lld surface pixels, %.0f ms):\n",
      100.0 * r.target, r.accuracy_width, r.accuracy_height, r.reference_pixels, r.reference_ms);
  for (const EnvironmentConvergencePoint& p : r.curve) {
    table.line("    %5d directions  relative RMSE %.4f  %10.1f ms\n", p.steps, p.relative_rmse,
               p.since_change_ms);
  }
  table.row("steps_to_target", r.steps_to_target, "", "directions per sample (0: not reached)");
  table.row("converge_ms", r.converge_ms, "ms", "camera change to that frame, all threads");
  table.row("converge_ratio", r.ratio, "x", "over the point-light 1-spp re-trace, same size");
  table.row("converge_ms_1thread", r.converge_ms_1, "ms", "the same on 1 thread");
  table.row("converge_ratio_1thread", r.ratio_1, "x", "over the 1-thread re-trace");
  table.row("converge_ratio_16_estimate", r.ratio_16, "x",
            "Amdahl's law through 1 and all threads");
  return table.text;
}

std::string environment_bench_json(const EnvironmentBenchReport& r) {
  nlohmann::json j;
  j["scene"] = r.scene;
  j["map"] = r.map;
  j["map_width"] = r.map_width;
  j["map_height"] = r.map_height;
  j["threads"] = r.threads;
  j["target_relative_rmse"] = r.target;
  j["prefilter_ms"] = r.prefilter_ms;
  j["point_retrace_ms"] = r.point_retrace_ms;
  j["fast_first_ms"] = r.fast_first_ms;
  j["fast_ratio"] = r.fast_ratio;
  j["reshade_ms"] = r.reshade_ms;
  j["floor_ms"] = r.floor_ms;
  j["reshade_ratio"] = r.reshade_ratio;
  j["reshade_mb"] = r.reshade_mb;
  j["accuracy_width"] = r.accuracy_width;
  j["accuracy_height"] = r.accuracy_height;
  j["reference_pixels"] = r.reference_pixels;
  j["reference_ms"] = r.reference_ms;
  nlohmann::json curve = nlohmann::json::array();
  for (const EnvironmentConvergencePoint& p : r.curve) {
    curve.push_back({{"steps", p.steps},
                     {"relative_rmse", p.relative_rmse},
                     {"since_change_ms", p.since_change_ms}});
  }
  j["curve"] = curve;
  j["steps_to_target"] = r.steps_to_target;
  j["converge_ms"] = r.converge_ms;
  j["retrace_ms"] = r.retrace_ms;
  j["converge_ratio"] = r.ratio;
  j["converge_ms_1thread"] = r.converge_ms_1;
  j["retrace_ms_1thread"] = r.retrace_ms_1;
  j["converge_ratio_1thread"] = r.ratio_1;
  j["converge_ratio_16_estimate"] = r.ratio_16;
  return j.dump(2);
}

}  // namespace gloss

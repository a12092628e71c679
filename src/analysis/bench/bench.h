#pragma once
// The engine benchmark behind `gloss-cli bench`: every figure is the median of several runs and
// every ratio is taken against a baseline measured in the same process (ray_baseline.h), as the
// median of the ratios within alternating pairs of runs.
#include <optional>
#include <string>
#include <vector>

#include "analysis/bench/bench_environment.h"
#include "analysis/bench/bench_scaling.h"
#include "scene/scene.h"

namespace gloss {

struct BenchOptions {
  int width = 1280, height = 720;  // pixels
  int runs = 7;           // repetitions per figure, the median reported; at least 15 for the ratios
  int converge_spp = 16;  // target of converge_16spp_ms and aa_ms
  int reference_spp = 256;  // of the image aa_rmse_ratio measures against
  std::vector<int> tessellation_levels{2, 4, 8, 16, 32};  // for scenes with a teapot
};

struct TessellationPoint {
  int level = 0;
  long long triangles = 0;
  double render_ms = 0;  // full 1-spp render, BVH already built
  double build_ms = 0;   // tessellation + Embree BVH build
};

struct BenchReport {
  std::string scene;
  int width = 0, height = 0, threads = 0;
  double retrace_ms = 0, embree_raw_ms = 0, retrace_ratio = 0;
  double retrace_terms_ms = 0;  // full render with the four term images too
  long long rays_per_frame = 0;
  double reshade_ms = 0, bandwidth_floor_ms = 0, reshade_ratio = 0;
  double reshade_terms_ms = 0;  // re-shade writing all four term images too
  double exponent_ms_alpha32 = 0, exponent_ms_alpha1e6 = 0;  // shininess edit re-shade
  double light_move_ms = 0;  // shadow rays + re-shade, primary hits reused
  double first_preview_ms = 0, converge_16spp_ms = 0;  // uniform sampling
  // Adaptive sampling at converge_spp: camera change to the converged image in the engine, that
  // over retrace_ms, and its RMSE over uniform sampling's, both against a uniform render at
  // reference_spp; the share of pixels it refined.
  double aa_ms = 0, aa_ratio = 0, aa_rmse_ratio = 0, aa_refined_share = 0;
  double aa_rmse = 0, uniform_rmse = 0;
  double single_thread_ms = 0, threads_speedup = 0;
  double cache_bytes_per_pixel = 0;          // per-pixel factors (what a constant edit reads)
  double sample_cache_bytes_per_sample = 0;  // per-sample cache (exponent and light edits)
  // Maps (texture_bench.h): a 2048 x 2048 map on every surface, normal maps on the quads.
  double textured_retrace_ms = 0, textured_retrace_ratio = 0;  // over the untextured re-trace
  double textured_reshade_ms = 0, textured_reshade_ratio = 0;  // kd edit, over today's
  double textured_bandwidth_floor_ms = 0;     // streaming the textured re-shade's bytes
  double textured_cache_bytes_per_pixel = 0;  // what the textured re-shade reads
  double peak_rss_mb = 0;        // of a plain render at this size in its own process (the CLI's)
  double bench_peak_rss_mb = 0;  // of this benchmark's process
  std::vector<TessellationPoint> tessellation;
  std::vector<ScalingPoint> scaling;                  // `--scaling` (bench_scaling.h), else empty
  std::optional<EnvironmentBenchReport> environment;  // `--environment` (bench_environment.h)
};

BenchReport run_benchmark(const Scene& scene, const BenchOptions& options);

// The readable table and the JSON object (keys as in the issue: retrace_ms, ...).
std::string format_bench_table(const BenchReport& report);
std::string bench_to_json(const BenchReport& report);

}  // namespace gloss

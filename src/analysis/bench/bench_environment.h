#pragma once
// The environment light's benchmark behind `gloss-cli bench --environment MAP` (issue 21's
// speed figures; docs/engine.md, "Benchmark: the environment"). Every ratio is taken against a
// baseline measured in the same process, the point-light 1-spp re-trace of the same scene (the
// scene without its environment):
//  (a) the fast path's first full image (levels already made; making them is timed apart);
//  (b) a material edit (kd) under the environment against the streaming floor of its bytes;
//  (c) the progressive path from the camera change to its first frame within `target` relative
//      RMSE (docs/accuracy.md) of the exact value, with 1 thread and with all, and the estimate
//      for 16 cores. The exact value is the reference path's (double, unshadowed: shadows are off
//      for (c), where the reference is a quadrature with a stated bound, not an estimate); it
//      costs milliseconds per pixel, so (c) runs at 1 / accuracy_divisor of the size and the
//      reference covers every reference_stride-th pixel of that (an unbiased sample of the
//      image's pixels: the RMSE over them estimates the RMSE over all).
#include <string>
#include <vector>

#include "scene/scene.h"

namespace gloss {

struct EnvironmentBenchOptions {
  int width = 1280, height = 720;  // (a) and (b)
  int runs = 7;                    // repetitions per figure (the medians); pairs at least 15
  int accuracy_divisor = 4;        // (c) at width / divisor x height / divisor
  int reference_stride = 2;        // the exact value on every stride-th pixel, both ways
  double target = 0.01;            // relative RMSE that counts as converged
  int max_steps = 4096;            // directions per sample at most in (c)
};

struct EnvironmentConvergencePoint {
  int steps = 0;               // directions per sample in the frame (0: the fast path)
  double relative_rmse = 0;    // against the exact value, surface pixels
  double since_change_ms = 0;  // from the camera change to the frame's publication
};

struct EnvironmentBenchReport {
  std::string scene, map;
  int map_width = 0, map_height = 0;
  double target = 0;        // options.target
  double prefilter_ms = 0;  // making every prefiltered level of the map (median, cold)
  int threads = 0;
  // (a) at width x height, paired.
  double point_retrace_ms = 0, fast_first_ms = 0, fast_ratio = 0;
  // (b) recombination of the total with the environment's factors, paired with the floor.
  double reshade_ms = 0, floor_ms = 0, reshade_ratio = 0;
  double reshade_mb = 0;  // bytes read and written per edit
  // (c)
  int accuracy_width = 0, accuracy_height = 0;
  long long reference_pixels = 0;  // surface pixels the error is taken over
  double reference_ms = 0;
  std::vector<EnvironmentConvergencePoint> curve;           // all threads, in order of publication
  int steps_to_target = 0;                                  // 0: not reached within max_steps
  double converge_ms = 0, retrace_ms = 0, ratio = 0;        // all threads
  double converge_ms_1 = 0, retrace_ms_1 = 0, ratio_1 = 0;  // one thread
  double ratio_16 = 0;  // estimated for 16 cores (Amdahl's law fitted to the two)
};

// scene: with its environment (its intensity, rotation); its other settings as given.
EnvironmentBenchReport run_environment_benchmark(const Scene& scene,
                                                 const EnvironmentBenchOptions& options);

std::string format_environment_bench_table(const EnvironmentBenchReport& report);
// The JSON object (text) the bench's report holds under "environment" (alone with
// `--environment-only`).
std::string environment_bench_json(const EnvironmentBenchReport& report);

}  // namespace gloss

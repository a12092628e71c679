#pragma once
// How the benchmark times: medians of repeated runs, and a figure against a baseline measured in
// alternating pairs, so the two of a pair see the same state of a noisy machine (a shared
// machine's speed drifts over minutes: docs/engine.md, "Benchmark timing").
#include <functional>

namespace gloss {

// Median wall time (ms) of f over runs repetitions, after one warm-up run.
double time_median(int runs, const std::function<void()>& f);

// f timed against a baseline g: medians of each (ms), and the median of the ratios f / g within
// pairs. The runs alternate (f, g, f, g ... after one warm-up of each); the median of the paired
// ratios is less disturbed by the machine's drift than the ratio of the two medians.
struct Paired {
  double f_ms, g_ms, ratio;
};
Paired time_paired(int runs, const std::function<void()>& f, const std::function<void()>& g);

}  // namespace gloss

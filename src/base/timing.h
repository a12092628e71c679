#pragma once
// Medians of repeated timings: the benchmark and the tradeoff measurement report them.
#include <algorithm>
#include <chrono>
#include <vector>

namespace gloss {

// The middle value (upper middle for an even count); 0 for none.
inline double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::nth_element(values.begin(), values.begin() + static_cast<long>(values.size() / 2),
                   values.end());
  return values[values.size() / 2];
}

// Milliseconds of steady-clock time since start.
inline double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace gloss

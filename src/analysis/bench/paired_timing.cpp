#include "analysis/bench/paired_timing.h"

#include <chrono>
#include <vector>

#include "base/timing.h"

namespace gloss {

double time_median(int runs, const std::function<void()>& f) {
  f();
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) {
    const auto start = std::chrono::steady_clock::now();
    f();
    t.push_back(ms_since(start));
  }
  return median(t);
}

Paired time_paired(int runs, const std::function<void()>& f, const std::function<void()>& g) {
  f();
  g();
  std::vector<double> tf, tg, ratios;
  for (int i = 0; i < runs; ++i) {
    auto start = std::chrono::steady_clock::now();
    f();
    tf.push_back(ms_since(start));
    start = std::chrono::steady_clock::now();
    g();
    tg.push_back(ms_since(start));
    ratios.push_back(tf.back() / tg.back());
  }
  return {median(tf), median(tg), median(ratios)};
}

}  // namespace gloss

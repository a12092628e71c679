#include "editor/ui/parts/frame_loop.h"

#include <algorithm>
#include <vector>

namespace gloss {

double Clock::now_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void FrameTimes::add(double value) {
  ms[next] = value;
  next = (next + 1) % kCount;
  size = std::min(size + 1, kCount);
}

double FrameTimes::average() const {
  double sum = 0.0;
  for (int i = 0; i < size; ++i) sum += ms[i];
  return size > 0 ? sum / size : 0.0;
}

double FrameTimes::median() const {
  if (size == 0) return 0.0;
  std::vector<double> sorted(ms, ms + size);
  std::nth_element(sorted.begin(), sorted.begin() + size / 2, sorted.end());
  return sorted[size / 2];
}

double FrameTimes::largest() const {
  double top = 0.0;
  for (int i = 0; i < size; ++i) top = std::max(top, ms[i]);
  return top;
}

}  // namespace gloss

#include "shading/sampling.h"

#include <cmath>

namespace gloss {

namespace {
int gcd(int a, int b) {
  while (b != 0) {
    const int t = a % b;
    a = b;
    b = t;
  }
  return a;
}
}  // namespace

SamplePattern make_sample_pattern(std::uint32_t seed, int count) {
  SamplePattern p;
  p.seed = seed;
  p.count = count < 1 ? 1 : count;
  p.side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(p.count))));
  p.square = p.side * p.side == p.count;
  // A stride near count * 0.618, coprime with count, so consecutive samples land in distant
  // strata and early progressive passes already cover the pixel.
  int stride = static_cast<int>(p.count * 0.6180339887) | 1;
  while (stride > 1 && gcd(stride, p.count) != 1) --stride;
  p.stride = stride < 1 ? 1 : stride;
  return p;
}

}  // namespace gloss

#pragma once
// Where the samples of a pixel fall. One sample is the pixel centre (spec/shading.md); N > 1
// samples are stratified: a jittered sqrt(N) x sqrt(N) grid when N is a square, else N-rooks
// (one sample in each of N rows and each of N columns). Jitter comes from a hash of
// (seed, pixel, sample), so the same seed gives the same image and the order of evaluation
// (progressive or one-shot, any thread count) does not matter.
#include <cstdint>

namespace gloss {

struct SampleOffset {
  float dx, dy;  // inside the pixel, in [0, 1)
};

SampleOffset sample_offset(std::uint32_t seed, int x, int y, int sample, int count);

}  // namespace gloss

#pragma once
// Where the samples of a pixel fall. One sample is the pixel centre (docs/spec/shading.md); N > 1
// samples are stratified: a jittered sqrt(N) x sqrt(N) grid when N is a square, else N-rooks
// (one sample in each of N rows and each of N columns). Jitter comes from a hash of
// (seed, pixel, stratum), so the same seed gives the same image and the order of evaluation
// (progressive or one-shot, any thread count) does not matter.
#include <cstdint>

namespace gloss {

struct SampleOffset {
  float dx, dy;  // inside the pixel, in [0, 1)
};

// What does not change from pixel to pixel: computed once per image.
struct SamplePattern {
  std::uint32_t seed = 0;
  int count = 1;   // samples per pixel
  int side = 1;    // sqrt(count) when count is a square
  int stride = 1;  // coprime with count: sample s lies in stratum (s * stride) mod count
  bool square = true;
};

SamplePattern make_sample_pattern(std::uint32_t seed, int count);

// A 32-bit integer mixer (the "lowbias32" constants of Chris Wellons' hash-prospector): cheap,
// stateless and good enough for jitter. Written here because no Debian package offers one.
inline std::uint32_t mix_bits(std::uint32_t h) {
  h ^= h >> 16;
  h *= 0x7feb352dU;
  h ^= h >> 15;
  h *= 0x846ca68bU;
  h ^= h >> 16;
  return h;
}

inline float unit_float(std::uint32_t h) {
  return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

inline int sample_stratum(const SamplePattern& p, int sample) {
  return static_cast<int>((static_cast<long long>(sample) * p.stride) % p.count);
}

// The offset of the sample in `stratum` of pixel (x, y) for a pattern of count > 1 that is
// (Square) or is not a square. Inline and branch-free in the lane: the renderer evaluates it
// for 16 lanes at a time (sample_offsets).
template <bool Square>
inline SampleOffset stratified_offset(const SamplePattern& p, int stratum, int x, int y) {
  const auto ux = static_cast<std::uint32_t>(x), uy = static_cast<std::uint32_t>(y);
  const std::uint32_t h = mix_bits(
      p.seed ^
      mix_bits(ux ^ mix_bits(uy ^ mix_bits(static_cast<std::uint32_t>(stratum) + 0x9e3779b9U))));
  const float jx = unit_float(h), jy = unit_float(mix_bits(h));
  float dx, dy;
  if constexpr (Square) {
    // Row and column of the stratum without an integer division (which keeps the lane loop
    // scalar): (stratum + 0.5) / side lies at least 1 / (2 side) >= 1/128 from an integer and
    // the float product is off by under 4e-6 for strata below kMaxSpp, so the row is exact.
    const int row = static_cast<int>((static_cast<float>(stratum) + 0.5f) *
                                     (1.0f / static_cast<float>(p.side)));
    const int column = stratum - row * p.side;
    dx = (static_cast<float>(column) + jx) / static_cast<float>(p.side);
    dy = (static_cast<float>(row) + jy) / static_cast<float>(p.side);
  } else {
    // N-rooks: column = stratum, row = a per-pixel affine permutation of it (mod count).
    const std::uint32_t hp = mix_bits(
        (p.seed ^ 0xa511e9b3U) ^
        mix_bits(ux ^ mix_bits(uy ^ mix_bits(static_cast<std::uint32_t>(p.count) + 0x9e3779b9U))));
    const auto count = static_cast<std::uint32_t>(p.count);
    const int row =
        static_cast<int>((static_cast<std::uint64_t>(stratum) * p.stride + hp % count) % count);
    dx = (static_cast<float>(stratum) + jx) / static_cast<float>(p.count);
    dy = (static_cast<float>(row) + jy) / static_cast<float>(p.count);
  }
  // Guard the open upper bound against rounding.
  if (dx >= 1.0f) dx = 0.99999994f;
  if (dy >= 1.0f) dy = 0.99999994f;
  return {dx, dy};
}

// The offset of the sample in `stratum` of pixel (x, y).
inline SampleOffset sample_offset(const SamplePattern& p, int stratum, int x, int y) {
  if (p.count <= 1) return {0.5f, 0.5f};
  return p.square ? stratified_offset<true>(p, stratum, x, y)
                  : stratified_offset<false>(p, stratum, x, y);
}

// sample_offset for n lanes, the pattern's branches taken once outside the loop.
inline void sample_offsets(const SamplePattern& p, const int* stratum, const int* x, const int* y,
                           int n, SampleOffset* out) {
  if (p.count <= 1) {
    for (int i = 0; i < n; ++i) out[i] = {0.5f, 0.5f};
  } else if (p.square) {
    for (int i = 0; i < n; ++i) out[i] = stratified_offset<true>(p, stratum[i], x[i], y[i]);
  } else {
    for (int i = 0; i < n; ++i) out[i] = stratified_offset<false>(p, stratum[i], x[i], y[i]);
  }
}

// Convenience for single samples (the reference path): the same positions as above.
inline SampleOffset sample_offset(std::uint32_t seed, int x, int y, int sample, int count) {
  const SamplePattern p = make_sample_pattern(seed, count);
  return sample_offset(p, sample_stratum(p, sample), x, y);
}

}  // namespace gloss

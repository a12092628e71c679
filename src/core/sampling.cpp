#include "sampling.h"

#include <cmath>

namespace gloss {

namespace {
// A 32-bit integer mixer (the "lowbias32" hash of Chris Wellons' hash-prospector): cheap,
// stateless and good enough for jitter. Written here because no Debian package offers one.
std::uint32_t mix(std::uint32_t h) {
  h ^= h >> 16;
  h *= 0x7feb352dU;
  h ^= h >> 15;
  h *= 0x846ca68bU;
  h ^= h >> 16;
  return h;
}

std::uint32_t hash4(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
  return mix(a ^ mix(b ^ mix(c ^ mix(d + 0x9e3779b9U))));
}

float unit_float(std::uint32_t h) {
  return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

// A stride coprime with n near n * 0.618, so consecutive samples land in distant strata and
// early progressive passes already cover the pixel.
int spread_stride(int n) {
  int stride = static_cast<int>(n * 0.6180339887) | 1;
  auto gcd = [](int a, int b) {
    while (b != 0) {
      const int t = a % b;
      a = b;
      b = t;
    }
    return a;
  };
  while (stride > 1 && gcd(stride, n) != 1) --stride;
  return stride < 1 ? 1 : stride;
}
}  // namespace

SampleOffset sample_offset(std::uint32_t seed, int x, int y, int sample, int count) {
  if (count <= 1) return {0.5f, 0.5f};
  const auto ux = static_cast<std::uint32_t>(x), uy = static_cast<std::uint32_t>(y);
  const int stratum =
      static_cast<int>((static_cast<long long>(sample) * spread_stride(count)) % count);
  const std::uint32_t h = hash4(seed, ux, uy, static_cast<std::uint32_t>(stratum));
  const float jx = unit_float(h), jy = unit_float(mix(h));
  const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(count))));
  float dx, dy;
  if (side * side == count) {
    dx = (static_cast<float>(stratum % side) + jx) / static_cast<float>(side);
    dy = (static_cast<float>(stratum / side) + jy) / static_cast<float>(side);
  } else {
    // N-rooks: column = stratum, row = a per-pixel permutation of it (affine map mod count).
    const std::uint32_t hp = hash4(seed ^ 0xa511e9b3U, ux, uy, static_cast<std::uint32_t>(count));
    const int a = spread_stride(count);
    const int row = static_cast<int>((static_cast<long long>(stratum) * a + hp % count) % count);
    dx = (static_cast<float>(stratum) + jx) / static_cast<float>(count);
    dy = (static_cast<float>(row) + jy) / static_cast<float>(count);
  }
  // Guard the open upper bound against rounding.
  if (dx >= 1.0f) dx = 0.99999994f;
  if (dy >= 1.0f) dy = 0.99999994f;
  return {dx, dy};
}

}  // namespace gloss

// The fast path's lane helpers: map coordinates of 16 directions at once (Cephes' atan, the GLSL
// path's polynomial) and the bilinear taps. Directions with coordinates known by hand (straight
// ahead, right, behind, the poles, 45 and 60 degrees), then a sweep against the C library's
// atan2/acos and against map_bilinear.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "base/image.h"
#include "engine/environment/environment_taps.h"
#include "engine/environment/environment_uv_lanes.h"
#include "shading/environment.h"

namespace gloss {
namespace {

struct Lanes {
  alignas(64) float x[kLanes], y[kLanes], z[kLanes], u[kLanes], t[kLanes];
};

TEST(EnvironmentLanes, MapCoordinatesOfKnownDirections) {
  const float h = std::sqrt(0.5f), s = std::sqrt(0.75f);
  // (x, y, z) and the (u, t) of the contract: u = 0.5 + atan2(x, -z) / (2 pi), t = acos(y) / pi.
  const float cases[][5] = {
      {0, 0, -1, 0.5f, 0.5f},         // straight ahead: the map's middle
      {1, 0, 0, 0.75f, 0.5f},         // right
      {-1, 0, 0, 0.25f, 0.5f},        // left
      {0, 0, 1, 1.0f, 0.5f},          // behind: atan2(0, -1) = +pi
      {0, 1, 0, 0.5f, 0.0f},          // the pole: phi taken as 0
      {0, -1, 0, 0.5f, 1.0f},         // the other pole
      {h, 0, -h, 0.625f, 0.5f},       // 45 degrees right
      {-h, 0, h, 0.125f, 0.5f},       // 135 degrees left
      {0, 0.5f, -s, 0.5f, 1 / 3.0f},  // 60 degrees from +y
      {s, -0.5f, 0, 0.75f, 2 / 3.0f},
  };
  Lanes l;
  constexpr int n = sizeof(cases) / sizeof(cases[0]);
  for (int i = 0; i < kLanes; ++i) {
    const float* c = cases[i % n];
    l.x[i] = c[0], l.y[i] = c[1], l.z[i] = c[2];
  }
  map_uv_lanes(l.x, l.y, l.z, l.u, l.t);
  for (int i = 0; i < kLanes; ++i) {
    EXPECT_NEAR(l.u[i], cases[i % n][3], 1e-6f) << "lane " << i;
    EXPECT_NEAR(l.t[i], cases[i % n][4], 1e-6f) << "lane " << i;
  }
}

TEST(EnvironmentLanes, MapCoordinatesAgreeWithTheLibrarysAtan2AndAcos) {
  // A Fibonacci sphere of 4096 directions, 16 at a time, against shading/environment.h map_uv
  // in double: the polynomial is good to about 1e-7 of the angle.
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  double worst = 0.0;
  for (int k0 = 0; k0 < 4096; k0 += kLanes) {
    Lanes l;
    for (int i = 0; i < kLanes; ++i) {
      const int k = k0 + i;
      const double y = 1.0 - (k + 0.5) / 2048.0, r = std::sqrt(1.0 - y * y);
      l.x[i] = static_cast<float>(r * std::cos(golden * k));
      l.y[i] = static_cast<float>(y);
      l.z[i] = static_cast<float>(r * std::sin(golden * k));
    }
    map_uv_lanes(l.x, l.y, l.z, l.u, l.t);
    for (int i = 0; i < kLanes; ++i) {
      const glm::dvec2 e = map_uv(glm::dvec3(l.x[i], l.y[i], l.z[i]));
      worst = std::max({worst, std::abs(l.u[i] - e.x), std::abs(l.t[i] - e.y)});
    }
  }
  std::printf("worst |(u, t) - exact| %.3g\n", worst);
  EXPECT_LT(worst, 4e-7);  // a texel of the finest map (8192 wide) is 1.2e-4
}

TEST(EnvironmentLanes, TapsReadWhatMapBilinearReads) {
  Image map(4, 2);  // texel (i, j) = (i + 10 j, 0, 1)
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 4; ++i) map.at(i, j) = glm::vec3(static_cast<float>(i + 10 * j), 0, 1);
  }
  alignas(64) float u[kLanes], t[kLanes];
  alignas(64) std::int32_t w[kLanes], hgt[kLanes];
  for (int i = 0; i < kLanes; ++i) {
    u[i] = static_cast<float>(i) / (kLanes - 1);  // 0 .. 1: both seams
    t[i] = static_cast<float>((i * 7) % kLanes) / (kLanes - 1);
    w[i] = 4, hgt[i] = 2;
  }
  BilinearTaps taps;
  bilinear_taps(u, t, w, hgt, taps);
  for (int i = 0; i < kLanes; ++i) {
    const glm::vec3 got = bilinear_value(map.pixels.data(), taps, i);
    const glm::vec3 want = map_bilinear<float>(map, u[i], t[i]);
    EXPECT_NEAR(got.x, want.x, 1e-5f) << "lane " << i;
    EXPECT_EQ(got.z, 1.0f) << "lane " << i;  // weights sum to 1
  }
  // By hand: u = 0 is between the last and first columns' centres (3 and 0: 1.5), t = 0 on the
  // top row; u = 1 the same seam.
  EXPECT_FLOAT_EQ(bilinear_value(map.pixels.data(), taps, 0).x, 1.5f + 0.0f);
  EXPECT_FLOAT_EQ(bilinear_value(map.pixels.data(), taps, kLanes - 1).x,
                  map_bilinear<float>(map, 1.0f, t[kLanes - 1]).x);
}

}  // namespace
}  // namespace gloss

// LaneGather fetches src[index[k]] whichever path it takes: the whole small table permuted,
// a 16-entry window permuted, or a real gather. Each case below is built to take one path,
// and every lane is checked against src[i] = 10 i + 1.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "engine/simd/lane_gather.h"

namespace gloss {
namespace {

std::vector<float> table(std::size_t n) {
  std::vector<float> src(n);
  for (std::size_t i = 0; i < n; ++i) src[i] = 10.0f * static_cast<float>(i) + 1.0f;
  return src;
}

void expect_fetched(const std::vector<float>& src, const std::int32_t (&index)[16]) {
  alignas(64) std::int32_t lanes[16];
  for (int k = 0; k < 16; ++k) lanes[k] = index[k];
  alignas(64) float out[16];
  const LaneGather gather(lanes);
  gather(src.data(), src.size(), out);
  for (int k = 0; k < 16; ++k) {
    EXPECT_EQ(out[k], 10.0f * static_cast<float>(index[k]) + 1.0f) << "lane " << k;
  }
}

TEST(LaneGather, SmallTableAnyOrder) {
  // 5 entries (a handful of materials): read with a masked load, nothing past the end.
  expect_fetched(table(5), {4, 0, 3, 3, 1, 2, 0, 4, 4, 4, 1, 1, 2, 0, 3, 2});
}

TEST(LaneGather, OneEntryForEveryLane) {
  expect_fetched(table(1000),
                 {417, 417, 417, 417, 417, 417, 417, 417, 417, 417, 417, 417, 417, 417, 417, 417});
}

TEST(LaneGather, NeighbouringEntriesUseTheWindow) {
  // Two triangles of a wall, and a spread of exactly 15 (the widest window).
  expect_fetched(table(1000),
                 {700, 700, 701, 701, 701, 700, 701, 700, 700, 700, 701, 701, 701, 701, 700, 700});
  expect_fetched(table(1000),
                 {500, 515, 503, 514, 501, 502, 509, 508, 507, 506, 505, 504, 510, 511, 512, 513});
}

TEST(LaneGather, WindowAtTheTableEnd) {
  // The window would run past the last entry: gathered instead.
  expect_fetched(table(40), {39, 38, 37, 36, 35, 34, 33, 32, 31, 30, 29, 28, 27, 26, 25, 39});
}

TEST(LaneGather, SpreadOutEntriesAreGathered) {
  expect_fetched(table(1000), {0, 999, 16, 500, 17, 3, 250, 251, 998, 1, 2, 600, 601, 602, 17, 0});
}

TEST(LaneGather, IntegerEntries) {
  const std::vector<std::uint32_t> src = {7u, 3000000000u, 42u};
  alignas(64) std::int32_t index[16];
  for (int k = 0; k < 16; ++k) index[k] = k % 3;
  alignas(64) std::uint32_t out[16];
  gather16(src.data(), src.size(), index, out);
  for (int k = 0; k < 16; ++k) EXPECT_EQ(out[k], src[static_cast<std::size_t>(k % 3)]);
}

}  // namespace
}  // namespace gloss

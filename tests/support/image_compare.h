#pragma once
// Small comparisons the image tests share.
#include <algorithm>

#include <gtest/gtest.h>
#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace gloss::test {

// The largest difference between two pixels in any channel.
inline double largest_channel_difference(const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 d = glm::abs(a - b);
  return std::max(d.x, std::max(d.y, d.z));
}

// A pixel against three expected channel values, each within tol (in a test body).
inline void expect_rgb(const glm::vec3& got, double r, double g, double b, double tol) {
  EXPECT_NEAR(got.x, r, tol);
  EXPECT_NEAR(got.y, g, tol);
  EXPECT_NEAR(got.z, b, tol);
}

}  // namespace gloss::test

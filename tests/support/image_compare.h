#pragma once
// Small comparisons the image tests share.
#include <algorithm>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace gloss::test {

// The largest difference between two pixels in any channel.
inline double largest_channel_difference(const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 d = glm::abs(a - b);
  return std::max(d.x, std::max(d.y, d.z));
}

}  // namespace gloss::test

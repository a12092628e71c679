#include "editor/model/view/heat_map.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

namespace gloss {

const glm::vec3 kHeatRamp[kHeatRampSize] = {{0.0f, 0.0f, 0.0f},
                                            {0.34f, 0.06f, 0.43f},
                                            {0.80f, 0.18f, 0.24f},
                                            {0.98f, 0.55f, 0.04f},
                                            {0.99f, 0.99f, 0.75f}};

glm::vec3 heat_colour(float t) {
  const float x = std::clamp(t, 0.0f, 1.0f) * (kHeatRampSize - 1);
  const int i = std::min(static_cast<int>(std::floor(x)), kHeatRampSize - 2);
  const float f = x - static_cast<float>(i);
  return kHeatRamp[i] * (1.0f - f) + kHeatRamp[i + 1] * f;
}

float max_difference(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) return 0.0f;
  float largest = 0.0f;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const glm::vec3 d = glm::abs(a.pixels[i] - b.pixels[i]);
    largest = std::max(largest, std::max(d.x, std::max(d.y, d.z)));
  }
  return largest;
}

}  // namespace gloss

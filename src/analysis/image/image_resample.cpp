#include "analysis/image/image_resample.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

namespace gloss {

namespace {
// Source coordinate of a target pixel centre along one axis: the two neighbours and the weight
// of the second.
struct Tap {
  int i0, i1;
  float w1;
};

Tap tap(int target, int target_size, int source_size) {
  const double s =
      (target + 0.5) * static_cast<double>(source_size) / static_cast<double>(target_size) - 0.5;
  const double clamped = std::clamp(s, 0.0, static_cast<double>(source_size - 1));
  const int i0 = static_cast<int>(std::floor(clamped));
  const int i1 = std::min(i0 + 1, source_size - 1);
  return {i0, i1, static_cast<float>(clamped - i0)};
}
}  // namespace

Image resize_bilinear(const Image& source, int width, int height) {
  if (source.width == width && source.height == height) return source;
  Image out(width, height);
  for (int y = 0; y < height; ++y) {
    const Tap ty = tap(y, height, source.height);
    for (int x = 0; x < width; ++x) {
      const Tap tx = tap(x, width, source.width);
      const glm::vec3 top = glm::mix(source.at(tx.i0, ty.i0), source.at(tx.i1, ty.i0), tx.w1);
      const glm::vec3 bottom = glm::mix(source.at(tx.i0, ty.i1), source.at(tx.i1, ty.i1), tx.w1);
      out.at(x, y) = glm::mix(top, bottom, ty.w1);
    }
  }
  return out;
}

}  // namespace gloss

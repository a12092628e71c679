#include "editor/model/view/log_drag.h"

#include <algorithm>
#include <cmath>

namespace gloss {

float log_drag_speed(float value, float floor) {
  return std::max(kLogDragPerPixel * std::abs(value), floor);
}

}  // namespace gloss

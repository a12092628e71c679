#include "editor/model/view/log_drag.h"

#include <algorithm>
#include <cmath>

namespace gloss {

float log_drag_value(float start, float dx, float per_pixel, float floor, float lo, float hi) {
  if (dx == 0.0f) return std::clamp(start, lo, hi);
  const double k = std::log1p(static_cast<double>(per_pixel));  // ln(1 + per_pixel)
  const double c = static_cast<double>(floor) / k;
  const double v = (static_cast<double>(start) + c) * std::exp(k * dx) - c;
  return static_cast<float>(std::clamp(v, static_cast<double>(lo), static_cast<double>(hi)));
}

float log_drag_per_pixel(bool shift, bool alt) {
  return kLogDragPerPixel * (shift ? 10.0f : 1.0f) * (alt ? 0.1f : 1.0f);
}

}  // namespace gloss

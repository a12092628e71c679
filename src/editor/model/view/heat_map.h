#pragma once
// The A/B view's difference heat map: one colour ramp shared by the display shader (as uniforms)
// and the legend drawn beside it, and the largest difference that sets the automatic scale.
#include <glm/vec3.hpp>

#include "base/image.h"

namespace gloss {

// Display colours (not linear) at t = 0, 1/4, 1/2, 3/4, 1, where t = difference / scale:
// black, violet, red, orange, pale yellow (an inferno-like ramp, readable in grey too).
constexpr int kHeatRampSize = 5;
extern const glm::vec3 kHeatRamp[kHeatRampSize];

// The ramp at t, clamped to [0, 1], interpolated linearly between stops as the shader does.
glm::vec3 heat_colour(float t);

// Largest per-channel |a - b| over all pixels (linear units); 0 for empty or mismatched sizes.
float max_difference(const Image& a, const Image& b);

}  // namespace gloss

#pragma once
// The exponent's drag widget: logarithmic, so a pixel is the same small step at alpha 5 and at
// alpha 5000. ImGui's logarithmic slider maps 0..10000 onto about 150 pixels (8% per pixel) and
// sets the value where the handle is pressed (a jump); a drag whose speed follows the value moves
// it by kLogDragPerPixel of itself per pixel from wherever it is, and never jumps on press.
namespace gloss {

constexpr float kLogDragPerPixel = 0.01f;  // 1% of the value per pixel (Shift: 10%, Alt: 0.1%)

// Drag speed (value units per pixel) at value: kLogDragPerPixel x |value|, at least floor so
// that a drag can leave 0.
float log_drag_speed(float value, float floor);

}  // namespace gloss

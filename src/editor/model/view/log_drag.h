#pragma once
// The exponent's drag widget: logarithmic, so a pixel is the same small step at alpha 5 and at
// alpha 5000. ImGui's logarithmic slider maps 0..10000 onto about 150 pixels (8% per pixel) and
// sets the value where the handle is pressed (a jump). This drag is a function of how far the
// mouse is from where it was pressed, not a sum of per-frame steps: dx pixels right of the press
// give (start + c) (1 + per_pixel)^dx - c, so a mouse that comes back brings the value back to
// its start exactly, however the motion was split into frames (a per-frame step of 1% of the
// value, +1% then -1%, loses 0.01% each time). c = floor / ln(1 + per_pixel) keeps the speed
// near 0 at floor per pixel, so a drag can leave 0.
namespace gloss {

constexpr float kLogDragPerPixel = 0.01f;  // 1% of the value per pixel (Shift: 10%, Alt: 0.1%)

// The value dx pixels from the press of a drag that started at start, per_pixel its relative
// step (kLogDragPerPixel, times the modifier's factor), floor the speed at 0 (value units per
// pixel), clamped to [lo, hi]. Exactly start at dx = 0.
float log_drag_value(float start, float dx, float per_pixel, float floor, float lo, float hi);

// The relative step per pixel with the modifiers held: Shift 10x, Alt 0.1x.
float log_drag_per_pixel(bool shift, bool alt);

}  // namespace gloss

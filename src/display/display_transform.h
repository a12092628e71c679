#pragma once
// The display transform: what a linear total becomes on screen and in a PNG
// (docs/spec/shading.md, "Output encodings"). Per channel x, in this order:
//   1. exposure: x * 2^exposure (stops);
//   2. tone curve: none (x), Reinhard x / (1 + x), or ACES, Narkowicz's fit
//      x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14);
//   3. clamp to [0, 1];
//   4. encoding: as is (the classic look) or sRGB.
// Values that are not above 0 (negatives, NaN) display as 0, as the clamp would leave them; the
// curves are applied to x >= 0 only (Reinhard has a pole at x = -1). PFM and EXR hold the linear
// total before all of it.
#include <cstddef>
#include <vector>

#include "base/image.h"
#include "scene/render_settings.h"

namespace gloss {

struct DisplayTransform {
  float gain = 1.0f;                 // 2^exposure
  ToneCurve tone = ToneCurve::none;  // after the gain
  bool srgb = false;                 // false: the clamped value as is
};

// The document's transform: render.exposure, render.tone, render.srgb.
DisplayTransform display_transform(const RenderSettings& render);
// The same transform with only its encoding (gain 1, no curve): for an image whose values are
// already display_linear's (an export with labels drawn after the transform).
DisplayTransform encoding_only(const DisplayTransform& display);

// The tone curve alone at x >= 0 (not clamped: ACES exceeds 1 from x = 7.24 on).
float tone_curve(float x, ToneCurve tone);
// Steps 1 and 2: the exposed and tone-mapped value, before the clamp (a value above 1 is what
// the display clips: exposure_histogram.h's and the shader's clipped pixels). >= 0; 0 for NaN.
float display_toned(float linear, const DisplayTransform& display);
// Steps 1 to 3: the displayed value before its encoding, in [0, 1].
float display_linear(float linear, const DisplayTransform& display);
// Step 4 alone: v in [0, 1] as is or sRGB-encoded.
float display_encode(float v, bool srgb);
// The linear value above which a channel clips (display_toned above 1): 1 / gain without a curve,
// the ACES curve's crossing / gain, +Inf for Reinhard (which never reaches 1). Found from
// display_toned itself, so the two agree on every float.
float clip_level(const DisplayTransform& display);
// All four steps: the displayed value, in [0, 1].
float display_value(float linear, const DisplayTransform& display);
// The 8-bit value a PNG holds: display_value rounded to nearest of 0..255.
unsigned char display_byte(float linear, const DisplayTransform& display);

// out[i] = display_value(in[i]) for n floats (in and out may be the same array); the loops are
// plain arithmetic per stage, so they run as vector code.
void display_values(const float* in, float* out, std::size_t n, const DisplayTransform& display);
// The image as displayed (every channel display_value), or display_linear when encode is false.
Image displayed_image(const Image& image, const DisplayTransform& display, bool encode = true);
// The image as a PNG holds it: display_byte of every channel, RGB, top row first.
std::vector<unsigned char> display_bytes(const Image& image, const DisplayTransform& display);

}  // namespace gloss

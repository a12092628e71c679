#include "display/display_transform.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gloss {

namespace {

// Exposed values are held below this before the curve: x (2.43 x + 0.59) stays finite in float
// and Reinhard's x / (1 + x) is 1 there, so +Inf displays as 1 like any large value.
constexpr float kLargest = 1e18f;

template <ToneCurve T>
inline float curve(float x) {
  if constexpr (T == ToneCurve::reinhard) {
    return x / (1.0f + x);
  } else if constexpr (T == ToneCurve::aces) {
    return x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f);
  } else {
    return x;
  }
}

// Steps 1 and 2 for one value; !(e > 0) also sends NaN to 0.
template <ToneCurve T>
inline float toned(float linear, float gain) {
  const float e = linear * gain;
  return curve<T>(e > 0.0f ? std::min(e, kLargest) : 0.0f);
}

inline float encode_srgb(float v) {
  return v < 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

// A displayed value in [0, 1] to 0..255, rounded to nearest.
inline unsigned char to_byte(float v) {
  return static_cast<unsigned char>(std::min(255.0f, std::floor(v * 255.0f + 0.5f)));
}

template <ToneCurve T>
void toned_clamped(const float* in, float* out, std::size_t n, float gain) {
  for (std::size_t i = 0; i < n; ++i) out[i] = std::min(toned<T>(in[i], gain), 1.0f);
}

void transform(const float* in, float* out, std::size_t n, const DisplayTransform& display,
               bool encode) {
  switch (display.tone) {
    case ToneCurve::none:
      toned_clamped<ToneCurve::none>(in, out, n, display.gain);
      break;
    case ToneCurve::reinhard:
      toned_clamped<ToneCurve::reinhard>(in, out, n, display.gain);
      break;
    case ToneCurve::aces:
      toned_clamped<ToneCurve::aces>(in, out, n, display.gain);
      break;
  }
  if (encode && display.srgb) {
    for (std::size_t i = 0; i < n; ++i) out[i] = encode_srgb(out[i]);
  }
}

}  // namespace

DisplayTransform display_transform(const RenderSettings& render) {
  DisplayTransform display;
  display.gain = std::exp2(render.exposure);
  display.tone = render.tone;
  display.srgb = render.srgb;
  return display;
}

DisplayTransform encoding_only(const DisplayTransform& display) {
  DisplayTransform out;
  out.srgb = display.srgb;
  return out;
}

float tone_curve(float x, ToneCurve tone) {
  switch (tone) {
    case ToneCurve::reinhard:
      return curve<ToneCurve::reinhard>(x);
    case ToneCurve::aces:
      return curve<ToneCurve::aces>(x);
    case ToneCurve::none:
      break;
  }
  return x;
}

float display_toned(float linear, const DisplayTransform& display) {
  switch (display.tone) {
    case ToneCurve::reinhard:
      return toned<ToneCurve::reinhard>(linear, display.gain);
    case ToneCurve::aces:
      return toned<ToneCurve::aces>(linear, display.gain);
    case ToneCurve::none:
      break;
  }
  return toned<ToneCurve::none>(linear, display.gain);
}

float clip_level(const DisplayTransform& display) {
  float lo = 0.0f, hi = 1.0f;  // display_toned(lo) <= 1 < display_toned(hi) once hi is found
  while (!(display_toned(hi, display) > 1.0f)) {
    if (hi > 1e30f) return std::numeric_limits<float>::infinity();
    hi *= 2.0f;
  }
  // Bisection down to adjacent floats: the largest value that does not clip is lo.
  while (std::nextafter(lo, hi) < hi) {
    const float mid = lo + 0.5f * (hi - lo);
    if (mid <= lo || mid >= hi) break;
    (display_toned(mid, display) > 1.0f ? hi : lo) = mid;
  }
  return lo;
}

float display_linear(float linear, const DisplayTransform& display) {
  float out = 0.0f;
  transform(&linear, &out, 1, display, false);
  return out;
}

float display_encode(float v, bool srgb) {
  return srgb ? encode_srgb(v) : v;
}

float display_value(float linear, const DisplayTransform& display) {
  float out = 0.0f;
  transform(&linear, &out, 1, display, true);
  return out;
}

unsigned char display_byte(float linear, const DisplayTransform& display) {
  return to_byte(display_value(linear, display));
}

void display_values(const float* in, float* out, std::size_t n, const DisplayTransform& display) {
  transform(in, out, n, display, true);
}

Image displayed_image(const Image& image, const DisplayTransform& display, bool encode) {
  Image out(image.width, image.height);
  if (image.pixels.empty()) return out;
  transform(&image.pixels.data()->x, &out.pixels.data()->x, image.pixels.size() * 3, display,
            encode);
  return out;
}

std::vector<unsigned char> display_bytes(const Image& image, const DisplayTransform& display) {
  const Image shown = displayed_image(image, display);
  std::vector<unsigned char> rgb(shown.pixels.size() * 3);
  for (std::size_t i = 0; i < shown.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = to_byte(shown.pixels[i][c]);
  }
  return rgb;
}

}  // namespace gloss

#pragma once
// Fast approximate c^alpha = exp2(alpha * log2 c) with polynomial log2 and exp2 (float only): a
// speed-for-accuracy knob whose error gloss-cli tradeoff measures. Inline and written with
// selects, not branches, so loops over lanes vectorize (power_lanes.cpp).
#include <cmath>
#include <cstdint>
#include <cstring>

namespace gloss {

// log2(x) for normal x > 0: exponent from the bits plus a degree-6 polynomial in t = m - 1 of
// the mantissa m in [1, 2) (least-squares fit to log2(1 + t), done in numpy on 20001 points:
// max abs error 4.4e-6 on the interval).
inline float fast_log2(float x) {
  std::uint32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const float e = static_cast<float>(static_cast<int>((bits >> 23) & 0xffu) - 127);
  bits = (bits & 0x007fffffu) | 0x3f800000u;
  float m;
  std::memcpy(&m, &bits, sizeof m);
  const float t = m - 1.0f;
  const float p =
      t * (1.44251703f +
           t * (-0.71789838f +
                t * (0.45689417f + t * (-0.27736505f + t * (0.12191414f + t * -0.0260663f)))));
  return e + p;
}

// 2^y for y <= 0: integer part into the exponent bits, the fraction f in [0, 1) by a degree-5
// polynomial (least-squares fit of 2^f, max relative error 1.4e-7 on the interval). Below the
// normal range (y < -126) the result is 0, the flushed value.
inline float fast_exp2(float y) {
  const bool underflow = y < -126.0f;
  const float fi = std::floor(underflow ? 0.0f : y);
  const float f = (underflow ? 0.0f : y) - fi;  // [0, 1)
  const float p =
      1.0f + f * (0.69315275f +
                  f * (0.24015319f + f * (0.05582818f + f * (0.00898895f + f * 0.00187664f))));
  const std::uint32_t bits = static_cast<std::uint32_t>(static_cast<int>(fi) + 127) << 23;
  float scale;
  std::memcpy(&scale, &bits, sizeof scale);
  return underflow ? 0.0f : p * scale;
}

// specular_power's contract (0 for c <= 0 or NaN, 1 for c >= 1 or alpha = 0), approximately; a
// denormal c (flushed in render threads) gives 0.
inline float fast_specular_power(float c, float alpha) {
  const bool zero = !(c > 0.0f);
  const bool one = c >= 1.0f || alpha == 0.0f;
  const bool tiny = c < 1.17549435e-38f;
  const float r = fast_exp2(alpha * fast_log2(zero || one || tiny ? 1.0f : c));
  return zero ? 0.0f : one ? 1.0f : tiny ? 0.0f : r;
}

}  // namespace gloss

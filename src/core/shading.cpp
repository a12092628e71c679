#include "shading.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace gloss {

namespace {
// log2(x) for normal x > 0: exponent from the bits plus a degree-6 polynomial in t = m - 1 of
// the mantissa m in [1, 2) (least-squares fit to log2(1 + t), done in numpy on 20001 points:
// max abs error 4.4e-6 on the interval).
float fast_log2(float x) {
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
// polynomial (least-squares fit of 2^f, max relative error 1.4e-7 on the interval).
float fast_exp2(float y) {
  if (y < -126.0f) return 0.0f;  // below the normal range: the flushed result
  const float fi = std::floor(y);
  const float f = y - fi;  // [0, 1)
  const float p =
      1.0f + f * (0.69315275f +
                  f * (0.24015319f + f * (0.05582818f + f * (0.00898895f + f * 0.00187664f))));
  const std::uint32_t bits = static_cast<std::uint32_t>(static_cast<int>(fi) + 127) << 23;
  float scale;
  std::memcpy(&scale, &bits, sizeof scale);
  return p * scale;
}
}  // namespace

float fast_specular_power(float c, float alpha) {
  if (!(c > 0.0f)) return 0.0f;
  if (c >= 1.0f || alpha == 0.0f) return 1.0f;
  if (c < 1.17549435e-38f) return 0.0f;  // denormal base: flushed to zero anyway
  return fast_exp2(alpha * fast_log2(c));
}

}  // namespace gloss

#include "engine/environment/scrambled_sobol.h"

#include "shading/sampling.h"

namespace gloss {

namespace {

std::uint32_t reverse_bits(std::uint32_t x) {
  x = (x << 16) | (x >> 16);
  x = ((x & 0x00ff00ffU) << 8) | ((x & 0xff00ff00U) >> 8);
  x = ((x & 0x0f0f0f0fU) << 4) | ((x & 0xf0f0f0f0U) >> 4);
  x = ((x & 0x33333333U) << 2) | ((x & 0xccccccccU) >> 2);
  x = ((x & 0x55555555U) << 1) | ((x & 0xaaaaaaaaU) >> 1);
  return x;
}

// A bijection of 32-bit words in which bit k of the result is bit k of x flipped by a function
// of the seed and of x's bits below k: adding, multiplying by an odd number and xoring in a
// multiple by an even number only carry upwards (Laine and Karras's construction, with Vegdahl's
// constants, which mix better than the paper's).
std::uint32_t upward_hash(std::uint32_t x, std::uint32_t seed) {
  x ^= x * 0x3d20adeaU;
  x += seed;
  x *= (seed >> 16) | 1U;
  x ^= x * 0x05526c56U;
  x ^= x * 0x53a22864U;
  return x;
}

}  // namespace

std::uint32_t sobol_dimension0(std::uint32_t i) {
  return reverse_bits(i);
}

// Sobol's second dimension is linear over bits: the xor of the direction numbers of i's set
// bits, here looked up a byte at a time.
struct Dimension1Tables {
  std::uint32_t byte[4][256];
  Dimension1Tables() {
    std::uint32_t v[32];
    v[0] = 1U << 31;  // direction numbers v_1 = 1/2, v_{k+1} = v_k xor v_k / 2 (3/4, 5/8, ...)
    for (int k = 1; k < 32; ++k) v[k] = v[k - 1] ^ (v[k - 1] >> 1);
    for (int b = 0; b < 4; ++b) {
      for (int x = 0; x < 256; ++x) {
        std::uint32_t r = 0;
        for (int k = 0; k < 8; ++k) {
          if ((x >> k) & 1) r ^= v[8 * b + k];
        }
        byte[b][x] = r;
      }
    }
  }
};

std::uint32_t sobol_dimension1(std::uint32_t i) {
  static const Dimension1Tables tables;
  return tables.byte[0][i & 0xffU] ^ tables.byte[1][(i >> 8) & 0xffU] ^
         tables.byte[2][(i >> 16) & 0xffU] ^ tables.byte[3][i >> 24];
}

std::uint32_t owen_scramble(std::uint32_t x, std::uint32_t seed) {
  // The fraction's first digit is its highest bit: reversed, the digits above a digit are the
  // bits below it, which is what upward_hash lets a bit depend on.
  return reverse_bits(upward_hash(reverse_bits(x), seed));
}

StepNumbers::StepNumbers(std::uint32_t key) {
  for (int pair = 0; pair < 3; ++pair) {
    const std::uint32_t base = mix_bits(key + 0x9e3779b9U * static_cast<std::uint32_t>(pair + 1));
    m_seeds[3 * pair] = base;
    m_seeds[3 * pair + 1] = mix_bits(base ^ 0x68e31da4U);
    m_seeds[3 * pair + 2] = mix_bits(base ^ 0xb5297a4dU);
  }
}

void StepNumbers::at(std::uint32_t step, double (&u)[6]) const {
  constexpr double kScale = 1.0 / 4294967296.0;  // 2^-32
  for (int pair = 0; pair < 3; ++pair) {
    // The shuffle, as a scramble of the index: every aligned block of 2^k steps stays a block
    // of 2^k consecutive points.
    const std::uint32_t index = owen_scramble(step, m_seeds[3 * pair]);
    const std::uint32_t x = owen_scramble(sobol_dimension0(index), m_seeds[3 * pair + 1]);
    const std::uint32_t y = owen_scramble(sobol_dimension1(index), m_seeds[3 * pair + 2]);
    u[2 * pair] = (static_cast<double>(x) + 0.5) * kScale;
    u[2 * pair + 1] = (static_cast<double>(y) + 0.5) * kScale;
  }
}

}  // namespace gloss

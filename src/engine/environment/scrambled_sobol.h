#pragma once
// The numbers behind the environment's directions (docs/engine.md, "The environment"): per
// cached sample and strategy (cosine, lobe, map) a two-dimensional Sobol sequence, Owen-scrambled
// and shuffled by a hash of the sample's key, so that the first 2^k steps of every sample are a
// (0, k, 2)-net: one point in each of the 2^k cells of every elementary grid (2^a x 2^b cells,
// a + b = k). Stratified draws turn an estimate's error from ~ n^-1/2 (independent draws) to
// ~ n^-3/4 where the integrand has edges (a light's rim, the horizon) and faster where it is
// smooth, while every step stays an unbiased draw (each point alone is uniform).
//
// The scrambles are Burley's hash-based Owen scrambling ("Practical Hash-based Owen Scrambling",
// JCGT 9(4), 2020): a hash in which every bit depends only on the bits below it, applied to the
// bit-reversed value. Written here because no Debian package offers it; the index shuffle is the
// same scramble applied to the step number, which keeps every aligned block of 2^k steps a
// block of 2^k consecutive Sobol points (so the progressive passes, 16 then doubling, each end
// on a net).
#include <cstdint>

namespace gloss {

// The first two dimensions of the Sobol sequence at index i, as 32-bit fractions: dimension 0
// the van der Corput sequence (i's bits reversed), dimension 1 Sobol's second (the Pascal
// matrix's direction numbers). Together a (0, 2)-sequence in base 2.
std::uint32_t sobol_dimension0(std::uint32_t i);
std::uint32_t sobol_dimension1(std::uint32_t i);

// A nested uniform (Owen) scramble of the 32-bit fraction x under seed: digit k of the result is
// digit k of x flipped by a hash of the seed and the digits above it.
std::uint32_t owen_scramble(std::uint32_t x, std::uint32_t seed);

// The numbers of one cached sample's steps: its seeds, made once from the sample's key.
class StepNumbers {
 public:
  StepNumbers() = default;
  explicit StepNumbers(std::uint32_t key);
  // The six numbers in [0, 1) of step `step`: (u[0], u[1]) for the cosine, (u[2], u[3]) for the
  // lobe, (u[4], u[5]) for the map, each pair its own scrambled and shuffled sequence.
  void at(std::uint32_t step, double (&u)[6]) const;

 private:
  std::uint32_t m_seeds[9] = {};  // per pair: the index shuffle's, then x's and y's scrambles
};

}  // namespace gloss

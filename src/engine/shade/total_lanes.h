#pragma once
// The total image of 16 pixels covered by one sample each, made in the pass that makes their
// factors (single_sample_pass.h) instead of reading the factors back (combine_terms): lane by
// lane the operations of Recombination::terms and total with weight 1, in the same order, so
// the pixels get the same bits either way (tests/engine/test_single_sample_pass.cpp).
#include <cstddef>
#include <cstdint>

#include "engine/shade/recombination.h"
#include "engine/simd/lanes.h"

namespace gloss {

class TotalLanes {
 public:
  explicit TotalLanes(const Recombination& recombination);

  // Adds planned light li's factor means (zero on missed lanes), lights in plan order.
  // material: the lanes' materials, 64-byte aligned, -1 where the sample missed.
  void add_light(const std::int32_t* material, std::size_t li, const float* diffuse,
                 const float* specular);

  // The lanes' totals, pixel by pixel (r, g, b), once every light is added. maps (when not
  // null): per term (emissive, ambient, diffuse, specular) the lanes' three multipliers from
  // the maps, or null for none, applied as combine_terms applies a pixel's texel channels.
  void store(const std::int32_t* material, float (&rgb)[3 * kLanes],
             const float* const (*maps)[4][3] = nullptr) const;

 private:
  void store_mapped(const std::int32_t* material, const float* const (&maps)[4][3],
                    float (&total)[3][kLanes]) const;

  const Recombination& m_recombination;
  alignas(64) float m_diffuse[3][kLanes];   // sum over lights of kd Ld diffuse
  alignas(64) float m_specular[3][kLanes];  // sum over lights of ks Ls specular
};

}  // namespace gloss

#pragma once
// out[k] = src[index[k]] for the 16 lanes of a packet. The lanes of a packet mostly index a few
// neighbouring entries (the two triangles of a wall, adjacent triangles of a mesh, a handful of
// materials or objects), and loading the 16 entries from the lowest index and permuting them
// cost about half a 16-lane AVX-512 gather where it was measured
// (docs/engine.md, "Lane fetches"). So a LaneGather finds the indices' range once and each fetch
// takes the window path when the range fits in 16 entries, the gather otherwise.
// Written with intrinsics because GCC's own vectorization of such loops stores lanes one by
// one and reads them back as a vector (a store-forwarding stall), or hoists the index scaling
// and falls back to 4-lane gathers. Both paths fetch the same values, so results do not depend
// on which one ran.
#include <cstddef>
#include <cstdint>
#include <cstring>

#if defined(__AVX512F__)
#include <immintrin.h>
#endif

#include "engine/simd/lanes.h"

namespace gloss {

static_assert(kLanes == 16, "the AVX-512 forms below hold one 512-bit register of lanes");

class LaneGather {
 public:
  // index: 16 lanes, 64-byte aligned, each within [0, size) of every array fetched.
  explicit LaneGather(const std::int32_t* index) {
#if defined(__AVX512F__)
    m_index = _mm512_load_si512(index);
    const __m512i first = _mm512_set1_epi32(index[0]);
    if (_mm512_cmpeq_epi32_mask(m_index, first) == 0xffff) {  // one entry: no reductions
      m_low = index[0];
      m_span = 0;
    } else {
      m_low = lowest(m_index);
      m_span = -lowest(_mm512_sub_epi32(_mm512_setzero_si512(), m_index)) - m_low;
    }
    m_offset = _mm512_sub_epi32(m_index, _mm512_set1_epi32(m_low));
#else
    m_index = index;
#endif
  }

  // Fetches src[index[k]] into out[k]; src holds size entries.
  template <class T>
  void operator()(const T* src, std::size_t size, T* out) const {
    static_assert(sizeof(T) == 4, "32-bit lanes");
#if defined(__AVX512F__)
    __m512i lanes;
    if (m_span == 0 && static_cast<std::size_t>(m_low) < size) {  // one entry: a broadcast
      std::int32_t bits;
      std::memcpy(&bits, src + m_low, sizeof bits);
      lanes = _mm512_set1_epi32(bits);
    } else if (size <=
               16) {  // the whole array in one register (masked: reads nothing past its end)
      const __mmask16 present = static_cast<__mmask16>((1u << size) - 1u);
      lanes =
          _mm512_maskz_permutexvar_epi32(0xffff, m_index, _mm512_maskz_loadu_epi32(present, src));
    } else if (m_span < 16 && static_cast<std::size_t>(m_low) + 16 <= size) {
      lanes = _mm512_maskz_permutexvar_epi32(0xffff, m_offset, _mm512_loadu_si512(src + m_low));
    } else {
      lanes = _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), 0xffff, m_index, src, 4);
    }
    _mm512_storeu_si512(out, lanes);
#else
    (void)size;
    for (int k = 0; k < kLanes; ++k) out[k] = src[m_index[k]];
#endif
  }

 private:
#if defined(__AVX512F__)
  // The smallest of 16 lanes. By hand: GCC 12's _mm512_reduce_min_epi32 and the plain
  // (unmasked) permutes trip its -Wuninitialized inside its own header, so
  // the masked forms throughout.
  static std::int32_t lowest(__m512i v) {
    constexpr __mmask16 all = 0xffff;
    v = _mm512_maskz_min_epi32(all, v, _mm512_maskz_shuffle_i32x4(all, v, v, 0x4e));  // 1 0 3 2
    v = _mm512_maskz_min_epi32(all, v, _mm512_maskz_shuffle_i32x4(all, v, v, 0xb1));  // 2 3 0 1
    v = _mm512_maskz_min_epi32(all, v, _mm512_maskz_shuffle_epi32(all, v, _MM_PERM_BADC));
    v = _mm512_maskz_min_epi32(all, v, _mm512_maskz_shuffle_epi32(all, v, _MM_PERM_CDAB));
    return _mm512_cvtsi512_si32(v);
  }

  __m512i m_index, m_offset;  // the lanes' indices, and their offsets from the lowest
  std::int32_t m_low, m_span;
#else
  const std::int32_t* m_index;
#endif
};

// One fetch (see LaneGather).
template <class T>
inline void gather16(const T* src, std::size_t size, const std::int32_t* index, T* out) {
  const LaneGather lanes(index);
  lanes(src, size, out);
}

}  // namespace gloss

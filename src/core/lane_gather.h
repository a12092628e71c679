#pragma once
// out[k] = src[index[k]] for the 16 lanes of a packet: one AVX-512 gather where the target has
// it. Written with intrinsics because GCC's own vectorization of such loops stores lanes one by
// one and reads them back as a vector (a store-forwarding stall), or hoists the index scaling
// and falls back to 4-lane gathers. index must be 64-byte aligned.
#include <cstdint>
#include <type_traits>

#if defined(__AVX512F__)
#include <immintrin.h>
#endif

namespace gloss {

template <class T>
inline void gather16(const T* src, const std::int32_t* index, T* out) {
  static_assert(sizeof(T) == 4, "32-bit lanes");
#if defined(__AVX512F__)
  const __m512i i = _mm512_load_si512(index);
  // The masked forms: the plain ones trip GCC 12's -Wuninitialized inside its own header.
  if constexpr (std::is_same_v<T, float>) {
    _mm512_storeu_ps(out, _mm512_mask_i32gather_ps(_mm512_setzero_ps(), 0xffff, i, src, 4));
  } else {
    _mm512_storeu_si512(out,
                        _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), 0xffff, i, src, 4));
  }
#else
  for (int k = 0; k < 16; ++k) out[k] = src[index[k]];
#endif
}

}  // namespace gloss

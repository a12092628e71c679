#pragma once
// Two-level table lookups for the kLanes primary hits of a packet: the record of primitive p of
// object k is base[k] + p * stride[k] and its kind is kind[k] (trace/surface_table.h keeps those
// per object). In registers with AVX-512: lanes stored one by one and read back as a vector
// stall on store forwarding.
#include <cstddef>
#include <cstdint>

#if defined(__AVX512F__)
#include <immintrin.h>
#endif

#include "engine/simd/lane_gather.h"
#include "engine/simd/lanes.h"

namespace gloss {

// Per-object columns of a two-level table, objects entries each.
struct ObjectColumns {
  const std::uint32_t* base;
  const std::uint32_t* stride;
  const std::int32_t* kind;
  std::size_t objects;
};

// Which kinds the lanes hold: `probe` among the lanes that hit something, `any` among all lanes.
struct KindsPresent {
  bool probe, any;
};

// record[i] and kind[i] (64-byte aligned) of lane i's (object[i], prim[i]); a lane with
// object < 0 gets record 0 and kind missed_kind. object and prim are 64-byte aligned.
inline KindsPresent lane_records(const std::int32_t* object, const std::uint32_t* prim,
                                 const ObjectColumns& table, std::int32_t missed_kind,
                                 std::int32_t probe_kind, std::int32_t any_kind,
                                 std::int32_t* record, std::int32_t* kind) {
#if defined(__AVX512F__)
  static_assert(kLanes == 16, "one 512-bit register of 32-bit lanes");
  const __m512i objects = _mm512_load_si512(object);
  const __m512i prims = _mm512_load_si512(prim);
  const std::int32_t first = object[0];
  const __mmask16 hit = _mm512_cmpge_epi32_mask(objects, _mm512_setzero_si512());
  __m512i base, stride, kinds;
  if (first >= 0 && _mm512_cmpeq_epi32_mask(objects, _mm512_set1_epi32(first)) == 0xffff) {
    // One object (most packets): its base, stride and kind.
    const std::size_t k = static_cast<std::size_t>(first);
    base = _mm512_set1_epi32(static_cast<std::int32_t>(table.base[k]));
    stride = _mm512_set1_epi32(static_cast<std::int32_t>(table.stride[k]));
    kinds = _mm512_set1_epi32(table.kind[k]);
  } else {
    alignas(64) std::int32_t index[kLanes], kind_lanes[kLanes];
    alignas(64) std::uint32_t bases[kLanes], strides[kLanes];
    _mm512_store_si512(index, _mm512_maskz_mov_epi32(hit, objects));  // missed lanes: 0
    const LaneGather by_object(index);
    by_object(table.base, table.objects, bases);
    by_object(table.stride, table.objects, strides);
    by_object(table.kind, table.objects, kind_lanes);
    base = _mm512_maskz_mov_epi32(hit, _mm512_load_si512(bases));
    stride = _mm512_load_si512(strides);
    kinds =
        _mm512_mask_mov_epi32(_mm512_set1_epi32(missed_kind), hit, _mm512_load_si512(kind_lanes));
  }
  _mm512_store_si512(record, _mm512_maskz_add_epi32(hit, base, _mm512_mullo_epi32(prims, stride)));
  _mm512_store_si512(kind, kinds);
  return {_mm512_mask_cmpeq_epi32_mask(hit, kinds, _mm512_set1_epi32(probe_kind)) != 0,
          _mm512_cmpeq_epi32_mask(kinds, _mm512_set1_epi32(any_kind)) != 0};
#else
  KindsPresent present = {false, false};
  for (int i = 0; i < kLanes; ++i) {
    const bool hit = object[i] >= 0;
    const std::size_t k = hit ? static_cast<std::size_t>(object[i]) : 0;
    record[i] = hit ? static_cast<std::int32_t>(table.base[k] + prim[i] * table.stride[k]) : 0;
    kind[i] = hit ? table.kind[k] : missed_kind;
    present.probe |= hit && kind[i] == probe_kind;
    present.any |= kind[i] == any_kind;
  }
  return present;
#endif
}

}  // namespace gloss

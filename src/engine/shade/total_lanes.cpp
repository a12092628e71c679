#include "engine/shade/total_lanes.h"

#include "engine/simd/lane_gather.h"
#include "engine/simd/lane_mask.h"
#include "shading/total.h"

namespace gloss {

namespace {
// Material indices to fetch the constants with: missed lanes read material 0 (if any) and
// discard it.
void material_index(const std::int32_t* material, std::int32_t (&index)[kLanes]) {
  for (int i = 0; i < kLanes; ++i) index[i] = material[i] < 0 ? 0 : material[i];
}

// For each channel c, two of the Recombination's constants for the lanes, gathered by
// material: columns first + c and second + c into a and b, then use(c, a, b). Missed lanes
// read material 0's constants (material_index); the caller discards them. A template so that
// use is inlined into the loop and its lane loops stay vectorized; always inlined because GCC
// otherwise keeps it out of line for add_light and store_mapped (a call per light and packet
// that the hand-written loops it replaced did not have).
template <class Use>
[[gnu::always_inline]] inline void gather_channel_pairs(const Recombination& recombination,
                                                        const std::int32_t* material,
                                                        std::size_t first, std::size_t second,
                                                        Use&& use) {
  alignas(64) std::int32_t index[kLanes];
  material_index(material, index);
  const LaneGather by_material(index);
  const std::size_t materials = recombination.materials();
  alignas(64) float a[kLanes], b[kLanes];
  for (std::size_t c = 0; c < 3; ++c) {
    by_material(recombination.column(first + c), materials, a);
    by_material(recombination.column(second + c), materials, b);
    use(c, a, b);
  }
}

// Channels to pixels: rgb[3 i + c] = total[c][i].
void interleave(const float (&total)[3][kLanes], float (&rgb)[3 * kLanes]) {
  for (int i = 0; i < kLanes; ++i) {
    for (int c = 0; c < 3; ++c) rgb[3 * i + c] = total[c][i];
  }
}
}  // namespace

TotalLanes::TotalLanes(const Recombination& recombination) : m_recombination(recombination) {
  for (int c = 0; c < 3; ++c) {
    for (int i = 0; i < kLanes; ++i) m_diffuse[c][i] = m_specular[c][i] = 0.0f;
  }
}

// `omp simd` (-fopenmp-simd): GCC otherwise unrolls these 16-lane loops and leaves them scalar.
void TotalLanes::add_light(const std::int32_t* material, std::size_t li, const float* diffuse,
                           const float* specular) {
  if (all_lanes_negative(material)) return;  // all missed: store ignores the sums
  const std::int32_t one = common_lane_value(material);
  if (one >= 0) {  // one material: its constants as scalars
    const std::size_t m = static_cast<std::size_t>(one);
    for (std::size_t c = 0; c < 3; ++c) {
      const float kd = m_recombination.column(6 + 6 * li + c)[m];
      const float ks = m_recombination.column(9 + 6 * li + c)[m];
#pragma omp simd
      for (int i = 0; i < kLanes; ++i) m_diffuse[c][i] += kd * diffuse[i];
#pragma omp simd
      for (int i = 0; i < kLanes; ++i) m_specular[c][i] += ks * specular[i];
    }
    return;
  }
  gather_channel_pairs(m_recombination, material, 6 + 6 * li, 9 + 6 * li,
                       [&](std::size_t c, const float(&kd)[kLanes], const float(&ks)[kLanes]) {
#pragma omp simd
                         for (int i = 0; i < kLanes; ++i) m_diffuse[c][i] += kd[i] * diffuse[i];
#pragma omp simd
                         for (int i = 0; i < kLanes; ++i) m_specular[c][i] += ks[i] * specular[i];
                       });
}

void TotalLanes::store(const std::int32_t* material, float (&rgb)[3 * kLanes],
                       const float* const (*maps)[4][3]) const {
  alignas(64) float total[3][kLanes];
  if (maps != nullptr && !all_lanes_negative(material)) {
    store_mapped(material, *maps, total);
    interleave(total, rgb);
    return;
  }
  if (all_lanes_negative(material)) {  // all missed: the terms are 0, the total 0 + background
    for (std::size_t c = 0; c < 3; ++c) {
      // Added to 0 as the general path does (a -0 or, with denormals off, a denormal background
      // then comes out as it does there).
      const float background = form_total(0.0f, 0.0f, 0.0f, 0.0f, m_recombination.background()[c]);
      for (int i = 0; i < kLanes; ++i) total[c][i] = background;
    }
    interleave(total, rgb);
    return;
  }
  const std::int32_t one = common_lane_value(material);
  if (one >= 0) {  // one material, every lane a hit: its constants as scalars
    const std::size_t m = static_cast<std::size_t>(one);
    for (std::size_t c = 0; c < 3; ++c) {
      const float emission = m_recombination.column(c)[m];
      const float ambient = m_recombination.column(3 + c)[m];
      const float missed_background = 0.0f * m_recombination.background()[c];
#pragma omp simd
      for (int i = 0; i < kLanes; ++i) {
        total[c][i] =
            form_total(emission, ambient, m_diffuse[c][i], m_specular[c][i], missed_background);
      }
    }
    interleave(total, rgb);
    return;
  }
  gather_channel_pairs(
      m_recombination, material, 0, 3,
      [&](std::size_t c, const float(&emission)[kLanes], const float(&ambient)[kLanes]) {
        const float background = m_recombination.background()[c];
#pragma omp simd
        for (int i = 0; i < kLanes; ++i) {
          // All terms zero on a missed lane.
          const bool hit = material[i] >= 0;
          const float missed = hit ? 0.0f : 1.0f;
          total[c][i] = form_total(hit ? emission[i] : 0.0f, hit ? ambient[i] : 0.0f,
                                   hit ? m_diffuse[c][i] : 0.0f, hit ? m_specular[c][i] : 0.0f,
                                   missed * background);
        }
      });
  interleave(total, rgb);
}

// The textured lanes: each term times its multipliers before the total is formed, in
// Recombination::terms' order (the scalar path of combine_terms; FMA contraction can fuse the
// products into the sums differently in the two, an ulp apart on some pixels). A term
// without a map is multiplied by 1 (exact), so the lane loop has no branch and vectorises; one
// material's constants are scalars, as in store.
void TotalLanes::store_mapped(const std::int32_t* material, const float* const (&maps)[4][3],
                              float (&total)[3][kLanes]) const {
  alignas(64) static const float kOnes[kLanes] = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
  auto channel = [&](std::size_t c, auto emission_at, auto ambient_at) {
    const float* m[4];
    for (int t = 0; t < 4; ++t) m[t] = maps[t][c] != nullptr ? maps[t][c] : kOnes;
    const float background = m_recombination.background()[c];
#pragma omp simd
    for (int i = 0; i < kLanes; ++i) {
      const bool hit = material[i] >= 0;
      total[c][i] = form_total(
          (hit ? emission_at(i) : 0.0f) * m[0][i], (hit ? ambient_at(i) : 0.0f) * m[1][i],
          (hit ? m_diffuse[c][i] : 0.0f) * m[2][i], (hit ? m_specular[c][i] : 0.0f) * m[3][i],
          (hit ? 0.0f : 1.0f) * background);
    }
  };
  const std::int32_t one = common_lane_value(material);
  if (one >= 0) {
    const std::size_t k = static_cast<std::size_t>(one);
    for (std::size_t c = 0; c < 3; ++c) {
      const float emission = m_recombination.column(c)[k];
      const float ambient = m_recombination.column(3 + c)[k];
      channel(
          c, [emission](int) { return emission; }, [ambient](int) { return ambient; });
    }
    return;
  }
  gather_channel_pairs(
      m_recombination, material, 0, 3,
      [&](std::size_t c, const float(&emission)[kLanes], const float(&ambient)[kLanes]) {
        channel(
            c, [&emission](int i) { return emission[i]; },
            [&ambient](int i) { return ambient[i]; });
      });
}

}  // namespace gloss

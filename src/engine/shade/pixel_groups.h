#pragma once
// The samples of one pixel summed by the material they hit (pixel_factors.h): the first
// material goes to the dense arrays, further ones (silhouettes) to a pass's extras. Shared by
// uniform sampling's planes and adaptive sampling's refined pixels.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "engine/shade/pixel_factors.h"

namespace gloss {

// The extras of one parallel chunk, appended to the factors in chunk order (deterministic
// whatever the thread count).
struct FactorExtras {
  std::vector<std::uint32_t> pixel;
  std::vector<std::int32_t> material;
  std::vector<float> weight, diffuse, specular;
  std::vector<float> textured;  // [extra * textured_stride] (textured_factors.h)

  void append_to(PixelFactors& out) const;
};

class PixelGroups {
 public:
  // textured: floats of a group's textured record (textured_factors.h); 0 for none.
  explicit PixelGroups(std::size_t lights, std::size_t textured = 0)
      : m_lights(lights), m_textured(textured) {}

  void clear() {
    m_groups.clear();
    m_sums.clear();
    m_records.clear();
    m_misses = 0;
  }

  // Counts one sample on `material` (< 0: a miss). Returns the sums it adds its factors to,
  // [2 * light] diffuse and [2 * light + 1] specular, or null for a miss; *record (when given)
  // is set to the group's textured record.
  float* add(std::int32_t material, float** record = nullptr) {
    if (material < 0) {
      ++m_misses;
      return nullptr;
    }
    std::size_t g = 0;
    while (g < m_groups.size() && m_groups[g].material != material) ++g;
    if (g == m_groups.size()) {
      m_groups.push_back({material, 0});
      // At least one float, so that a hit returns non-null without lights (no slots: an
      // ambient-only scene) and its textured record still gets its samples.
      m_sums.resize(m_sums.size() + std::max<std::size_t>(2 * m_lights, 1), 0.0f);
      m_records.resize(m_records.size() + m_textured, 0.0f);
    }
    ++m_groups[g].count;
    if (record != nullptr) *record = m_records.data() + g * m_textured;
    return m_sums.data() + g * 2 * m_lights;
  }

  // Writes pixel idx's means over its samples (inv_n = 1 / their count): the first material to
  // out's dense arrays (its textured record to *record, when textured), its weight and the
  // background share to `weight` and `background`, the other materials to extras.
  void write(std::size_t idx, float inv_n, PixelFactors& out, float& weight, float& background,
             FactorExtras& extras, float* record = nullptr) const;

 private:
  struct Group {
    std::int32_t material;
    int count;
  };
  std::size_t m_lights;
  std::size_t m_textured;
  std::vector<Group> m_groups;
  std::vector<float> m_sums;     // [group * 2 * lights + 2 * light + {0: diffuse, 1: specular}]
  std::vector<float> m_records;  // [group * textured + j]
  int m_misses = 0;
};

}  // namespace gloss

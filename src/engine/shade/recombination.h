#pragma once
// The linear part of the shading contract: the material constants folded with the light colours
// and the scene ambient, per material (ke; ka (A_scene + sum La); per planned light kd Ld_i and
// ks Ls_i, the latter times the optional energy normalisation; per environment slot kd and ks
// in its channel times the intensity), applied to per-pixel factor means (pixel_factors.h):
// what combine_terms applies to every pixel.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/render_context.h"
#include "shading/total.h"

namespace gloss {

class Recombination {
 public:
  explicit Recombination(const RenderContext& ctx);

  std::size_t lights() const { return m_lights; }
  std::size_t materials() const { return m_materials; }
  const glm::vec3& background() const { return m_background; }

  // Constant j of every material, by material index: the flat table's column j (0-2 ke, 3-5
  // ka (A + sum La), then per light kd Ld and ks Ls), for code that fetches it for 16 lanes at
  // once (total_lanes.h).
  const float* column(std::size_t j) const { return m_columns.data() + j * m_materials; }

  // One material's four terms (emissive, ambient, diffuse, specular) in one pixel, from its
  // weight and per-light factor means: light li's at diffuse[li * step], specular[li * step].
  void terms(std::int32_t material, float weight, const float* diffuse, const float* specular,
             std::size_t step, glm::vec3 term[4]) const {
    const float* f = &m_flat[static_cast<std::size_t>(material) * m_stride];
    term[0] = weight * glm::vec3(f[0], f[1], f[2]);
    term[1] = weight * glm::vec3(f[3], f[4], f[5]);
    term[2] = glm::vec3(0.0f);
    term[3] = glm::vec3(0.0f);
    for (std::size_t li = 0; li < m_lights; ++li) {
      const float* k = f + 6 + 6 * li;
      term[2] += glm::vec3(k[0], k[1], k[2]) * diffuse[li * step];
      term[3] += glm::vec3(k[3], k[4], k[5]) * specular[li * step];
    }
  }

  // One material group's four terms from a textured record (textured_factors.h): the means of
  // the maps' multipliers times the factors, per channel.
  void textured_terms(std::int32_t material, const float* record, glm::vec3 term[4]) const {
    const float* f = &m_flat[static_cast<std::size_t>(material) * m_stride];
    term[0] = glm::vec3(f[0], f[1], f[2]) * glm::vec3(record[3], record[4], record[5]);
    term[1] = glm::vec3(f[3], f[4], f[5]) * glm::vec3(record[0], record[1], record[2]);
    term[2] = glm::vec3(0.0f);
    term[3] = glm::vec3(0.0f);
    for (std::size_t li = 0; li < m_lights; ++li) {
      const float* k = f + 6 + 6 * li;
      const float* r = record + 6 + 6 * li;
      term[2] += glm::vec3(k[0], k[1], k[2]) * glm::vec3(r[0], r[1], r[2]);
      term[3] += glm::vec3(k[3], k[4], k[5]) * glm::vec3(r[3], r[4], r[5]);
    }
  }

  // A pixel's total from its first material's terms and its share of missed samples.
  glm::vec3 total(const glm::vec3 term[4], float missed) const {
    return form_total(term[0], term[1], term[2], term[3], missed * m_background);
  }
  // The same where the environment is the background: sky is the pixel's mean over its samples
  // of the map where they missed (intensity 1).
  glm::vec3 total_under_sky(const glm::vec3 term[4], const glm::vec3& sky) const {
    return form_total(term[0], term[1], term[2], term[3], sky * m_sky_intensity);
  }
  // Whether the environment is shown where primary rays miss (as_background with a sky).
  bool sky_shown() const { return m_sky_shown; }

 private:
  std::size_t m_lights = 0;
  std::size_t m_stride = 6;  // floats per material in m_flat
  // Per material: ke, ka (A + sum La), then per light kd Ld, ks Ls; 3 floats each.
  std::vector<float> m_flat;
  std::size_t m_materials = 0;
  std::vector<float> m_columns;  // m_flat by column: [j * materials + material]
  glm::vec3 m_background{0.0f};
  bool m_sky_shown = false;
  float m_sky_intensity = 0.0f;
};

}  // namespace gloss

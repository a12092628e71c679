#pragma once
// The environment light's fast path (docs/engine.md, "The environment"): the map convolved once
// with the normalised Phong lobe max(0, r.w)^alpha for alpha = 0, 1, 2, 4, ... 1024, each level
// an equirectangular image as fine as its lobe needs. At a hit the diffuse term is level 1
// (the clamped cosine: E(n) / pi) at n, the specular term the levels around alpha at the mirror
// direction r, interpolated in log2 alpha, and above alpha 1024 blended towards the map itself
// (the mirror limit, reached at 16384). What it cannot know is measured, not hidden: the horizon
// H(w) of the contract's lobe, the Blinn-Phong lobe's dependence on v (it takes the Phong level
// of alpha / 4, the usual equivalence), visibility (no shadows), and its own resolution
// (`gloss-cli tradeoff`, docs/accuracy.md). The raster path samples the same levels.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "base/image.h"
#include "scene/environment.h"
#include "scene/render_settings.h"

namespace gloss {

// Levels up to this exponent are prefiltered; beyond it the specular term blends towards the map
// (the mirror image) and is the map itself from kEnvironmentMirrorExponent on.
inline constexpr float kTopPrefilteredExponent = 1024.0f;
inline constexpr float kEnvironmentMirrorExponent = 16384.0f;

struct PrefilterSettings {
  // Texels per lobe width (1 / sqrt(alpha) radians) across each level and across the map level
  // it is computed from: the "map resolution" knob. 2 keeps bilinear lookups within about 3 %
  // of the exact convolution on sharp features; every level is at least 128 x 64 for alpha
  // <= 1 and 64 x 32 above, and at most the map's own size.
  int texels_per_lobe = 2;
  bool operator==(const PrefilterSettings& o) const { return texels_per_lobe == o.texels_per_lobe; }
};

// Which images a lobe of exponent alpha reads: level a and, weighted wb, level b (b ==
// levels() means the map itself).
struct LevelBlend {
  int a = 0, b = 0;
  float wb = 0.0f;
};

class PrefilteredEnvironment {
 public:
  // Convolves map (intensity 1, rotation 0: both are applied at lookup) on oneTBB workers.
  PrefilteredEnvironment(std::shared_ptr<const EnvironmentMap> map,
                         const PrefilterSettings& settings);

  int levels() const { return static_cast<int>(m_levels.size()); }
  float exponent(int level) const { return m_exponents[static_cast<std::size_t>(level)]; }
  // Level k's image; k == levels() is the map itself.
  const Image& image(int k) const;
  const EnvironmentMap& map() const { return *m_map; }
  const PrefilterSettings& settings() const { return m_settings; }

  LevelBlend blend(float alpha) const;

  // The fast path's terms at intensity 1 for map-frame unit directions (shading/environment.h,
  // to_map_frame): the diffuse term's irradiance / pi at normal n, the specular term's lobe mean
  // of exponent alpha at the mirror direction r.
  glm::vec3 diffuse(const glm::vec3& n) const;
  glm::vec3 specular(float alpha, const glm::vec3& r) const { return specular(blend(alpha), r); }
  // The same with the levels already chosen (per material, once: EnvironmentContext).
  glm::vec3 specular(const LevelBlend& blend, const glm::vec3& r) const;
  // The same at map coordinates (u, t) already computed (the lanes compute them all at once:
  // environment_uv_lanes.h).
  glm::vec3 diffuse_at(float u, float t) const;
  glm::vec3 specular_at(const LevelBlend& blend, float u, float t) const;

  std::uint64_t bytes() const;

 private:
  std::shared_ptr<const EnvironmentMap> m_map;
  PrefilterSettings m_settings;
  std::vector<float> m_exponents;
  std::vector<Image> m_levels;
};

// The Phong exponent whose level stands for a lobe of the model: alpha itself for Phong, alpha / 4
// for Blinn-Phong (the half-vector lobe is about four times as wide).
inline float phong_equivalent_exponent(ShadingModel model, float alpha) {
  return model == ShadingModel::phong ? alpha : 0.25f * alpha;
}

// The prefiltered levels of map at settings, shared: made the first time and kept while some
// holder (or the last few uses) need them, so an edit that keeps the map does not redo them.
std::shared_ptr<const PrefilteredEnvironment> prefiltered_environment(
    const std::shared_ptr<const EnvironmentMap>& map, const PrefilterSettings& settings);

}  // namespace gloss

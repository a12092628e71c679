#include "engine/adaptive/adaptive_progression.h"

#include <utility>
#include <vector>

#include "engine/adaptive/adaptive_refinement.h"
#include "engine/adaptive/centre_ring.h"
#include "engine/adaptive/refined_samples.h"

namespace gloss {

void AdaptiveProgression::edit(ChangeClass change, const SampleCache& cache) {
  if (change == ChangeClass::full) return;  // restart() follows
  if (cache.refined.spp == 0) return;       // nothing refined yet: the first refine() chooses
  m_placement_stale = true;
  if (change == ChangeClass::light) m_lights_stale = true;
}

void AdaptiveProgression::restart() {
  m_placement_stale = m_lights_stale = false;
}

bool AdaptiveProgression::current(const SampleCache& cache, int spp) const {
  return cache.refined.spp >= spp && !m_placement_stale && !m_lights_stale;
}

bool AdaptiveProgression::build_factors(const SampleCache& cache, const RenderContext& ctx,
                                        PixelFactors& factors) const {
  return m_lights_stale ? build_centre_factors(cache, ctx, factors)
                        : build_pixel_factors(cache, ctx, factors);
}

bool AdaptiveProgression::refine(SampleCache& cache, const RenderContext& ctx,
                                 PixelFactors& factors, const Image* centre_total) {
  // The total the centre samples make, what the rule reads. A shade or exponent edit's first
  // image kept the refined pixels of the older placement, so it is not that image.
  if (centre_total == nullptr) {
    if (!build_centre_factors(cache, ctx, factors)) return false;
    combine_terms(factors, ctx, m_centres, false);
    centre_total = &m_centres.total;
  }
  const RenderSettings& r = ctx.scene->render;
  // The centres beyond the image's edges, for the current camera, lights and materials: a few
  // thousand samples, traced again each time rather than kept in step with every edit.
  CentreRing ring;
  if (!trace_centre_ring(cache, ctx, ring)) return false;
  std::vector<std::uint32_t> pixels;
  if (!choose_refined_pixels(cache, ring, *centre_total, r, 0, cache.height, ctx.cancel, pixels)) {
    return false;
  }
  RefinedUpdate update;
  bool ok;
  if (cache.refined.spp == 0) {
    update.traced = pixels.size();
    ok = trace_refined_samples(cache, ctx, std::move(pixels), r.spp);
  } else {
    ok = update_refined_samples(cache, ctx, std::move(pixels), m_lights_stale, m_spare, &update);
  }
  if (!ok) return false;
  m_traced = update.traced;
  m_placement_stale = m_lights_stale = false;
  // The factors hold the centres' (the caller's, or built above); the refined pixels get theirs.
  return refine_pixel_factors(cache, ctx, factors);
}

}  // namespace gloss

#pragma once
// Adaptive sampling's state between the progressive engine's passes (progressive_renderer.h):
// which pixels the cache's refined samples cover, and whether those still belong to the current
// scene. An edit that keeps the primary hits (shade, exponent, light) leaves a placement chosen
// from an older centre image: refine() chooses it again from the new one, traces only the pixels
// newly refined (and re-lights the kept ones after a light edit) and drops the others, so the
// converged image is render()'s, placement and all.
#include <cstddef>

#include "base/image.h"
#include "engine/change_class.h"
#include "engine/render_context.h"
#include "engine/shade/pixel_factors.h"
#include "engine/trace/sample_cache.h"

namespace gloss {

class AdaptiveProgression {
 public:
  // The engine took in an edit of class `change`; cache holds the centres it had before.
  void edit(ChangeClass change, const SampleCache& cache);
  // A new image (camera, geometry, sampling): it has no refined samples yet.
  void restart();
  // The refined samples are those the rule chooses for the current scene, at spp per pixel.
  bool current(const SampleCache& cache, int spp) const;

  // The cache's pixel factors: the centres and the refined samples, or the centres alone while
  // the refined samples' light factors are those of older lights. false when cancelled.
  bool build_factors(const SampleCache& cache, const RenderContext& ctx,
                     PixelFactors& factors) const;
  // Chooses the refined pixels from the current centre image (centre_total when the caller holds
  // it, with `factors` then the centres'; else made here from the centres), brings the refined
  // samples to that placement at ctx.scene's spp, and makes the factors of centres and refined
  // samples. false when cancelled.
  bool refine(SampleCache& cache, const RenderContext& ctx, PixelFactors& factors,
              const Image* centre_total);
  // Pixels whose refined samples the last refine() traced afresh.
  std::size_t traced() const { return m_traced; }

 private:
  bool m_placement_stale = false;  // chosen from an older centre image
  bool m_lights_stale = false;     // the refined samples' light factors are of older lights
  TermImages m_centres;            // the centre image when the caller has none
  SamplePlane m_spare;             // memory for update_refined_samples
  std::size_t m_traced = 0;
};

}  // namespace gloss

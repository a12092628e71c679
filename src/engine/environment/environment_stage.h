#pragma once
// The environment's stages over a cached image (engine's own): its factors recomputed from the
// cached hits when only the environment changed (another map or rotation, or an exponent under
// it), and the sky, the map seen by the primary rays that hit nothing (docs/engine.md, "The
// environment").
#include "engine/render_context.h"
#include "engine/shade/pixel_factors.h"
#include "engine/trace/sample_cache.h"

namespace gloss {

// The environment's three slots of every cached sample (planes and refined samples) anew, by the
// fast path at ctx's maps and rotation, from the cached hits: no ray is traced. false when
// cancelled (the slots are then stale).
bool recompute_environment_factors(SampleCache& cache, const RenderContext& ctx);

// factors.sky: per pixel the mean over its samples of the map's radiance at intensity 1 where
// they missed (combine_terms shows it in place of the background colour when the environment is
// the background); emptied when the plan has no sky. false when cancelled.
bool environment_sky(const SampleCache& cache, const RenderContext& ctx, PixelFactors& factors);

}  // namespace gloss

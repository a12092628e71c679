#include "engine/renderer.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "engine/adaptive/adaptive_refinement.h"
#include "engine/environment/environment_estimate.h"
#include "engine/environment/environment_stage.h"
#include "engine/render_context.h"
#include "engine/shade/pixel_factors.h"
#include "engine/adaptive/centre_ring.h"
#include "engine/trace/embree_scene.h"
#include "engine/adaptive/refined_samples.h"
#include "engine/trace/sample_cache.h"
#include "engine/trace/single_sample_pass.h"
#include "scene/fields/validation.h"
#include "scene/memory/memory_estimate.h"

namespace gloss {

namespace {
// Copies `rows` rows of band from its row `from` to image rows from row0.
void copy_rows(const Image& band, int from, int rows, int row0, Image& image) {
  std::memcpy(&image.pixels[static_cast<std::size_t>(row0) * image.width],
              &band.pixels[static_cast<std::size_t>(from) * band.width],
              static_cast<std::size_t>(rows) * band.width * sizeof(glm::vec3));
}
}  // namespace

TermImages render(const Scene& scene, const RenderOptions& options) {
  validate_scene(scene);
  const EmbreeScene embree(scene);
  RenderContext ctx;
  bind_scene(ctx, scene, embree, options.full_plan);

  const int w = scene.render.width, h = scene.render.height, spp = scene.render.spp;
  // Larger images go band by band, each band's sample cache about kSampleBandBytes; validation
  // counted the same (scene/memory/memory_estimate.h).
  const int band_rows = sample_band_rows(w, h, spp, ctx.plan.slots());

  TermImages out;
  out.total = Image(w, h);
  if (options.terms) {
    out.emissive = out.ambient = out.diffuse = out.specular = Image(w, h);
  }
  const bool adaptive = spp > 1 && scene.render.sampling == Sampling::adaptive;
  // The environment's exact terms: the estimates replace the fast path's factors before the
  // image is made. Its sky: made by the fused 1-spp pass with the total, else by
  // environment_sky, and shown by combine_terms.
  EnvironmentEstimates environment;
  const bool exact = next_environment_steps(ctx, environment) > 0;
  if (options.refined != nullptr) options.refined->clear();
  SampleCache cache;
  PixelFactors factors;
  TermImages band;
  for (int row0 = 0; row0 < h; row0 += band_rows) {
    const int rows = std::min(band_rows, h - row0);
    // Adaptive bands carry a row of their neighbours' centres on each side, so the rule sees
    // what it sees in a whole image and the placement does not depend on the banding.
    const int halo0 = adaptive ? std::max(0, row0 - 1) : row0;
    const int halo1 = adaptive ? std::min(h, row0 + rows + 1) : row0 + rows;
    cache = make_sample_cache(scene, w, h, adaptive ? 1 : spp, halo0, halo1 - halo0);
    if (adaptive) {
      trace_single_sample(cache, ctx, factors, &band.total);
      const auto region0 = static_cast<std::uint32_t>(halo0 * w);  // image index of region 0
      std::vector<std::uint32_t> pixels;
      if (options.placement != nullptr) {
        const auto first = std::lower_bound(options.placement->begin(), options.placement->end(),
                                            static_cast<std::uint32_t>(row0 * w));
        const auto last = std::lower_bound(first, options.placement->end(),
                                           static_cast<std::uint32_t>((row0 + rows) * w));
        for (auto p = first; p != last; ++p) pixels.push_back(*p - region0);
      } else {
        CentreRing ring;
        // render() is not cancellable (ctx.cancel is null), so this never fails.
        if (!trace_centre_ring(cache, ctx, ring)) throw std::logic_error("render: the ring failed");
        pixels = choose_refined_pixels(cache, ring, band.total, scene.render, row0 - halo0,
                                       row0 - halo0 + rows);
      }
      trace_refined_samples(cache, ctx, std::move(pixels), spp);
      build_pixel_factors(cache, ctx, factors);
      if (options.refined != nullptr) {
        for (const std::uint32_t p : cache.refined.pixels) options.refined->push_back(p + region0);
      }
    } else if (spp == 1) {  // the same bits, one pass (with the total, unless terms are wanted)
      trace_single_sample(cache, ctx, factors, options.terms || exact ? nullptr : &band.total);
    } else {
      add_samples(cache, ctx, spp);
      build_pixel_factors(cache, ctx, factors);
    }
    if (exact) {
      environment.reset();
      add_environment_steps(cache, ctx, environment, scene.render.env_samples);
      build_pixel_factors(cache, ctx, factors);
    }
    // The fused 1-spp pass made the total, and the sky with it.
    const bool fused = !adaptive && spp == 1 && !options.terms && !exact;
    if (!fused) {
      environment_sky(cache, ctx, factors);
      combine_terms(factors, ctx, band, options.terms);
    }
    const int from = row0 - halo0;
    copy_rows(band.total, from, rows, row0, out.total);
    if (options.terms) {
      copy_rows(band.emissive, from, rows, row0, out.emissive);
      copy_rows(band.ambient, from, rows, row0, out.ambient);
      copy_rows(band.diffuse, from, rows, row0, out.diffuse);
      copy_rows(band.specular, from, rows, row0, out.specular);
    }
  }
  return out;
}

}  // namespace gloss

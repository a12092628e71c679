#pragma once
// The first full-resolution pass of an image, fused: each packet's sample is traced, cached and
// turned into pixel factors while its lanes are still in registers, instead of writing the
// cache and reading it back (build_pixel_factors). The result equals
// add_samples(cache, ctx, 1) followed by build_pixel_factors, bit for bit. Given a total image,
// the pass also writes the total combine_terms would make of the factors (the same bits), so a
// view of the total needs no second pass; with an environment it writes the sky as well
// (factors.sky, as environment_sky would, shown where the environment is the background), so
// no sky pass is needed either.
#include "base/image.h"
#include "engine/render_context.h"
#include "engine/shade/pixel_factors.h"
#include "engine/trace/sample_cache.h"

namespace gloss {

// Any samples the cache holds are dropped first. total, when given, is resized to the cached
// region. false when cancelled (the cache is then left empty and the factors and total
// incomplete).
bool trace_single_sample(SampleCache& cache, const RenderContext& ctx, PixelFactors& factors,
                         Image* total = nullptr);

// One sample at each image point (px[i], py[i]) (pixels, image rows; outside the image too) into
// strip, whose pixel i (row by row) is point i (pixels past n repeat the last point), the
// directions made as image's (its camera and size); the factors and total as
// trace_single_sample makes them at pixel centres. strip's width and height are the caller's;
// the call gives it image's camera, image height and seed, and one plane. false when cancelled.
bool trace_single_sample_at(SampleCache& strip, const SampleCache& image, const double* px,
                            const double* py, std::size_t n, const RenderContext& ctx,
                            PixelFactors& factors, Image* total);

// For a cache of one sample per pixel (a light edit in the first full-resolution pass): the
// light factors from the cached hits and the pixel factors in one pass, equal to
// recompute_light_factors followed by build_pixel_factors. false when cancelled (factors, total
// and light factors are then stale).
bool relight_single_sample(SampleCache& cache, const RenderContext& ctx, PixelFactors& factors,
                           Image* total = nullptr);

}  // namespace gloss

#pragma once
// Adaptive sampling's rule: which pixels of the centre-sampled image (one sample per pixel at
// its centre) get spp stratified samples. A pixel is refined when some pixel of its 3 x 3
// neighbourhood
//   - sees another object (or the background where it sees one): silhouettes and contacts;
//   - is lit by a planned light where it is not, or the reverse (spec_weight > 0 differs):
//     shadow edges and the terminator, where Phong's specular lobe is cut off;
//   - differs in the total (linear, unclamped: the values images and metrics hold) by more
//     than `threshold` in some channel: highlights, flat-shaded facets, steep gradients.
//   - is itself where the total curves: its 4-neighbour Laplacian exceeds threshold / 10 in some
//     channel (the tip of a highlight narrower than the step test sees).
// Pixels on the image border are always refined: beyond them lies no centre to compare with,
// and an edge just outside the last row of centres (a floor ending at the bottom of the frame)
// would otherwise go unseen.
// Both sides of an edge are refined. What it cannot see: detail that falls between pixel
// centres (geometry thinner than a pixel, a highlight smaller than one) leaves no trace in the
// centre image and stays unrefined (docs/accuracy.md, "Where adaptive sampling misses").
#include <atomic>
#include <cstdint>
#include <vector>

#include "base/image.h"
#include "engine/trace/sample_cache.h"

namespace gloss {

// The refined pixels (region indices, ascending) of rows [row_begin, row_end) of the cache's
// region; neighbours are looked up anywhere in the region. cache.planes[0] holds the centre
// samples; total is the region's total image made from them.
std::vector<std::uint32_t> choose_refined_pixels(const SampleCache& cache, const Image& total,
                                                 float threshold, int row_begin, int row_end);
// The same into out, stopping soon after cancel turns true: false then (out is incomplete).
bool choose_refined_pixels(const SampleCache& cache, const Image& total, float threshold,
                           int row_begin, int row_end, const std::atomic<bool>* cancel,
                           std::vector<std::uint32_t>& out);

}  // namespace gloss

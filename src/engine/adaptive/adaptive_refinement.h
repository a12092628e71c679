#pragma once
// Adaptive sampling's rule: which pixels of the centre-sampled image (one sample per pixel at
// its centre) get spp stratified samples. A pixel is refined when some pixel of its 3 x 3
// neighbourhood
//   - sees another object (or the background where it sees one): silhouettes and contacts;
//   - is lit by a planned light where it is not, or the reverse (spec_weight > 0 differs):
//     shadow edges and the terminator, where Phong's specular lobe is cut off;
// or when the displayed total curves at the pixel itself: its 4-neighbour Laplacian exceeds
// render.aa_threshold / 10 in some channel. Displayed: through the document's display transform
// (display/display_transform.h: exposure, tone curve, clamp, encoding), so the rule reads what a
// user sees: two values a clamp shows as the same white are not an edge. The Laplacian sees a
// colour edge (a step s gives +-s on its two sides), a highlight's tip and a crease between
// facets, but not a smooth gradient however steep, where the centre is its pixel's mean to
// within Laplacian / 24: a step test between neighbours (refine where they differ by more than
// aa_threshold) had refined such gradients, up to a third of the refined pixels of the shipped
// scenes, and left as many or more pixels off the 256-spp reference (docs/accuracy.md).
// Pixels on the image border are compared with the centres just outside the image
// (adaptive/centre_ring.h), like any other: an edge just outside the last row of centres (a floor
// ending at the bottom of the frame) is seen there. (The border used to be refined whole.)
// What it cannot see: detail that falls between pixel centres (geometry thinner than a pixel, a
// highlight smaller than one) leaves no trace in the centre image and stays unrefined
// (docs/accuracy.md, "Where adaptive sampling misses").
#include <atomic>
#include <cstdint>
#include <vector>

#include "base/image.h"
#include "engine/adaptive/centre_ring.h"
#include "engine/trace/sample_cache.h"
#include "scene/render_settings.h"

namespace gloss {

// The refined pixels (region indices, ascending) of rows [row_begin, row_end) of the cache's
// region; neighbours are looked up anywhere in the region and in ring, the region's centre ring
// (trace_centre_ring). cache.planes[0] holds the centre samples; total is the region's linear
// total image made from them; render gives the threshold and the display transform.
std::vector<std::uint32_t> choose_refined_pixels(const SampleCache& cache, const CentreRing& ring,
                                                 const Image& total, const RenderSettings& render,
                                                 int row_begin, int row_end);
// The same into out, stopping soon after cancel turns true: false then (out is incomplete).
bool choose_refined_pixels(const SampleCache& cache, const CentreRing& ring, const Image& total,
                           const RenderSettings& render, int row_begin, int row_end,
                           const std::atomic<bool>* cancel, std::vector<std::uint32_t>& out);

}  // namespace gloss

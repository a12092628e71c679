#pragma once
// The centres just outside the image, for adaptive sampling's rule (adaptive_refinement.h): one
// sample at the centre of each pixel position beyond the image's left and right edges, and
// beyond its top and bottom rows, traced and shaded as the image's own centres are (the fused
// 1-spp pass). With them a pixel on the image border is compared with neighbours like any other,
// instead of being refined because nothing lay beyond it (the border had been 0.4 % of the
// benchmark scene's pixels, a tenth of those refined, most of them flat background).
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/render_context.h"
#include "engine/trace/sample_cache.h"

namespace gloss {

// For a cached region of `width` pixels by `height` rows: the points x = -1 and x = width of each
// region row, and, where the region holds the image's first row, the row above it (x = -1 ..
// width), where it holds the last, the row below.
struct CentreRing {
  int width = 0, height = 0;
  bool top = false, bottom = false;
  // Per point (index below): the object hit (-1: none), each light slot's spec_weight (> 0: lit
  // and visible), the linear total.
  std::vector<std::int32_t> object;
  std::vector<std::vector<float>> spec_weight;  // [slot][point]
  std::vector<glm::vec3> total;

  std::size_t points() const { return object.size(); }
  // Region row r's left (x = -1) and right (x = width) points.
  std::size_t left(int r) const { return 2 * static_cast<std::size_t>(r); }
  std::size_t right(int r) const { return 2 * static_cast<std::size_t>(r) + 1; }
  // The row above (top) or below (bottom) at x = -1 .. width.
  std::size_t above(int x) const { return 2 * static_cast<std::size_t>(height) + 1 + x; }
  std::size_t below(int x) const {
    return 2 * static_cast<std::size_t>(height) + (top ? width + 2 : 0) + 1 + x;
  }
};

// The ring of the cache's region (its camera, image size and rows), traced and shaded with ctx
// into ring, as the fused 1-spp pass shades the centres: with the environment's fast path, also
// where the centre image holds its exact estimates (env_samples > 0), so a border pixel's
// curvature may then see the fast path beside it. false when cancelled (ring is then
// incomplete).
bool trace_centre_ring(const SampleCache& cache, const RenderContext& ctx, CentreRing& ring);

}  // namespace gloss

#include "engine/adaptive_refinement.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "display/display_transform.h"
#include "engine/parallel_loops.h"

namespace gloss {

namespace {
// Bits of a pixel's edge flags: whether it differs from its right, lower-right, lower and
// lower-left neighbour. Each pair of neighbours is compared once.
enum : std::uint8_t { kRight = 1, kDownRight = 2, kDown = 4, kDownLeft = 8 };

// out[i] |= bit where region pixels a + i and b + i differ by the rule, i < n; shown_a and
// shown_b are their displayed totals (r, g, b each). Plain loops over the cache's own arrays, so
// they run as vector code and allocate nothing.
void mark_differences(const SamplePlane& plane, const float* shown_a, const float* shown_b,
                      std::size_t a, std::size_t b, int n, float threshold, std::uint8_t bit,
                      std::uint8_t* out) {
  const std::int32_t *oa = &plane.object[a], *ob = &plane.object[b];
  const float* ta = shown_a;
  const float* tb = shown_b;
  for (int i = 0; i < n; ++i) {
    const bool d = (oa[i] != ob[i]) | (std::fabs(ta[3 * i] - tb[3 * i]) > threshold) |
                   (std::fabs(ta[3 * i + 1] - tb[3 * i + 1]) > threshold) |
                   (std::fabs(ta[3 * i + 2] - tb[3 * i + 2]) > threshold);
    out[i] |= d ? bit : 0;
  }
  for (const LightFactorPlane& light : plane.lights) {  // lit and visible on one side only
    const float *sa = &light.spec_weight[a], *sb = &light.spec_weight[b];
    for (int i = 0; i < n; ++i) out[i] |= (sa[i] > 0.0f) != (sb[i] > 0.0f) ? bit : 0;
  }
}
// The curvature test's threshold as a share of the step threshold. Where the image is smooth a
// centre differs from its pixel's mean by about Laplacian / 24; at a highlight sharper than the
// centres resolve it differs more. 1/10 is the largest share that refined every pixel of the
// shipped scenes whose centre sat more than 1e-3 from the 256-spp mean where uniform 16 spp did
// not (the last, on the teapot's highlight, at a Laplacian of 0.0019; docs/accuracy.md).
constexpr float kCurvatureShare = 0.1f;

// refine[x] |= 1 where the displayed row mid's 4-neighbour Laplacian (rows up and down beside
// it) exceeds threshold in some channel; columns 0 and w - 1 are border pixels anyway. Pixel by
// pixel with its three channels side by side: one flag per pixel, no scatter into refine.
void mark_curvature(const float* __restrict up, const float* __restrict mid,
                    const float* __restrict down, int w, float threshold,
                    std::uint8_t* __restrict refine) {
  for (int x = 1; x + 1 < w; ++x) {
    bool curved = false;
    for (int c = 0; c < 3; ++c) {
      const int i = 3 * x + c;
      const float laplacian = mid[i - 3] + mid[i + 3] + up[i] + down[i] - 4.0f * mid[i];
      curved |= std::fabs(laplacian) > threshold;
    }
    refine[x] |= curved ? 1 : 0;
  }
}

// refine[x] = whether pixel x of a row has an edge that differs: its own 4 flags (e), its left
// neighbour's kRight and, given the row above (up), that row's kDown at x, kDownRight at x - 1
// and kDownLeft at x + 1. Raw pointers, restrict-qualified: byte stores may alias anything, and
// through vectors the compiler reloaded every pointer per pixel and kept the loops scalar.
void gather_edges(const std::uint8_t* __restrict e, const std::uint8_t* __restrict up, int w,
                  std::uint8_t* __restrict refine) {
  refine[0] = e[0];
  for (int x = 1; x < w; ++x) refine[x] = e[x] | (e[x - 1] & kRight);
  if (up == nullptr) return;
  refine[0] |= (up[0] & kDown) | (w > 1 ? up[1] & kDownLeft : 0);
  for (int x = 1; x + 1 < w; ++x) {
    refine[x] |= (up[x] & kDown) | (up[x - 1] & kDownRight) | (up[x + 1] & kDownLeft);
  }
  if (w > 1) refine[w - 1] |= (up[w - 1] & kDown) | (up[w - 2] & kDownRight);
}

// Appends base + x for each x with refine[x] != 0, ascending. Eight flags at a time: most of a
// row is not refined.
void collect_refined(const std::uint8_t* refine, int w, std::uint32_t base,
                     std::vector<std::uint32_t>& out) {
  int x = 0;
  for (; x + 8 <= w; x += 8) {
    std::uint64_t word;
    std::memcpy(&word, refine + x, sizeof word);
    if (word == 0) continue;
    for (int i = x; i < x + 8; ++i) {
      if (refine[i] != 0) out.push_back(base + static_cast<std::uint32_t>(i));
    }
  }
  for (; x < w; ++x) {
    if (refine[x] != 0) out.push_back(base + static_cast<std::uint32_t>(x));
  }
}

// One band's working memory, kept by each thread between calls: the displayed rows and the edge
// flags a band reads (a few hundred KB), so a pass allocates and faults in nothing per band. A
// band starts no parallel work, so a thread never holds two bands at once.
struct BandScratch {
  std::vector<float> shown;
  std::vector<std::uint8_t> edges, refine;
};

}  // namespace

std::vector<std::uint32_t> choose_refined_pixels(const SampleCache& cache, const Image& linear,
                                                 const RenderSettings& render, int row_begin,
                                                 int row_end) {
  std::vector<std::uint32_t> out;
  choose_refined_pixels(cache, linear, render, row_begin, row_end, nullptr, out);
  return out;
}

// Band by band in one parallel pass: a band displays the rows it looks at (its own and one on
// each side, each row by itself, so a row's displayed values do not depend on the banding),
// compares neighbours into edge flags (the row above the band again, for its lower flags) and
// collects its refined pixels. Before, the whole image was displayed into a new image and the
// flags made in a pass of their own: three passes over memory and 12 bytes a pixel allocated
// and zeroed, 14 ms on the benchmark scene (one thread) beside some 30 ms of refined rays.
bool choose_refined_pixels(const SampleCache& cache, const Image& linear,
                           const RenderSettings& render, int row_begin, int row_end,
                           const std::atomic<bool>* cancel, std::vector<std::uint32_t>& out) {
  out.clear();
  const float threshold = render.aa_threshold;
  const DisplayTransform display = display_transform(render);
  const int w = cache.width, h = cache.height;
  const auto stride = static_cast<std::size_t>(w) * 3;  // floats per displayed row
  const SamplePlane& plane = cache.planes.at(0);
  const auto pixel = [&](int x, int y) { return static_cast<std::size_t>(y) * w + x; };
  // A pixel is refined when one of its 8 edges differs: its own 4 flags, or the flag its left,
  // upper-left, upper and upper-right neighbours hold towards it. The image border always:
  // beyond it lies no centre to compare with. Per band of rows its refined pixels, joined in
  // band order (ascending).
  const int rows = band_rows(w), chosen = row_end - row_begin;
  std::vector<std::vector<std::uint32_t>> bands(
      static_cast<std::size_t>(std::max(0, (chosen + rows - 1) / rows)));
  const bool chose = parallel_rows(w, chosen, cancel, [&](int r0, int r1) {
    std::vector<std::uint32_t>& band = bands[static_cast<std::size_t>(r0 / rows)];
    thread_local BandScratch scratch;
    const int y0 = row_begin + r0, y1 = row_begin + r1;
    // Displayed rows [s0, s1): the band's, and its neighbours within the region.
    const int s0 = std::max(0, y0 - 1), s1 = std::min(h, y1 + 1);
    scratch.shown.resize(static_cast<std::size_t>(s1 - s0) * stride);
    for (int y = s0; y < s1; ++y) {
      display_values(&linear.pixels[pixel(0, y)].x, &scratch.shown[(y - s0) * stride], stride,
                     display);
    }
    const auto shown = [&](int x, int y) { return &scratch.shown[(y - s0) * stride + 3 * x]; };
    // Edge flags of rows [s0, y1), index (y - s0) * w + x.
    scratch.edges.assign(static_cast<std::size_t>(y1 - s0) * w, 0);
    const auto edges = [&](int y) { return &scratch.edges[static_cast<std::size_t>(y - s0) * w]; };
    for (int y = s0; y < y1; ++y) {
      std::uint8_t* e = edges(y);
      auto mark = [&](int xa, int xb, int yb, int n, std::uint8_t bit, std::uint8_t* flags) {
        mark_differences(plane, shown(xa, y), shown(xb, yb), pixel(xa, y), pixel(xb, yb), n,
                         threshold, bit, flags);
      };
      mark(0, 1, y, w - 1, kRight, e);
      if (y + 1 >= h) continue;  // the last row has no lower neighbours
      mark(0, 1, y + 1, w - 1, kDownRight, e);
      mark(0, 0, y + 1, w, kDown, e);
      mark(1, 0, y + 1, w - 1, kDownLeft, e + 1);
    }
    scratch.refine.resize(static_cast<std::size_t>(w));
    std::uint8_t* const refine = scratch.refine.data();
    for (int y = y0; y < y1; ++y) {
      gather_edges(edges(y), y > s0 ? edges(y - 1) : nullptr, w, refine);
      if (y > 0 && y + 1 < h) {
        mark_curvature(shown(0, y - 1), shown(0, y), shown(0, y + 1), w,
                       threshold * kCurvatureShare, refine);
      }
      const int row = cache.row0 + y;  // image row
      if (row == 0 || row == cache.image_height - 1) std::fill(refine, refine + w, 1);
      refine[0] = refine[w - 1] = 1;
      collect_refined(refine, w, static_cast<std::uint32_t>(pixel(0, y)), band);
    }
  });
  if (!chose) return false;
  for (const auto& band : bands) out.insert(out.end(), band.begin(), band.end());
  return true;
}

}  // namespace gloss

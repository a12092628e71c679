#include "engine/adaptive/adaptive_refinement.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "display/display_transform.h"
#include "engine/parallel_loops.h"

namespace gloss {

namespace {
// Bits of a pixel's edge flags: whether it differs from its right, lower-right, lower and
// lower-left neighbour. Each pair of neighbours is compared once.
enum : std::uint8_t { kRight = 1, kDownRight = 2, kDown = 4, kDownLeft = 8 };

// The curvature test's threshold as a share of aa_threshold. Where the image is smooth a centre
// differs from its pixel's mean by about Laplacian / 24; at an edge or a highlight sharper than
// the centres resolve it differs more. 1/10 is the largest share that refined every pixel of the
// shipped scenes whose centre sat more than 1e-3 from the 256-spp mean where uniform 16 spp did
// not (the last, on the teapot's highlight, at a Laplacian of 0.0019; docs/accuracy.md).
constexpr float kCurvatureShare = 0.1f;

// One row of centres as the rule reads it, padded: entry 0 is the point left of the region's
// first column, entry width + 1 the point right of its last (CentreRing), entries 1 .. width the
// region's own pixels. The object hit, the lit bits of every slot, the displayed total.
struct PaddedRow {
  std::int32_t* object;
  std::uint32_t* lit;  // `words` per entry
  float* shown;        // r, g, b per entry
};

// out[i] |= bit where entries a + i of row ra and b + i of row rb differ by the rule, i < n:
// another object, or another lit state for some slot. Plain loops, so they run as vector code.
void mark_differences(const PaddedRow& ra, int a, const PaddedRow& rb, int b, int n, int words,
                      std::uint8_t bit, std::uint8_t* __restrict out) {
  const std::int32_t* __restrict oa = ra.object + a;
  const std::int32_t* __restrict ob = rb.object + b;
  for (int i = 0; i < n; ++i) out[i] |= oa[i] != ob[i] ? bit : 0;
  if (words == 1) {  // up to 32 slots: a contiguous loop, vector code (the strided one is not)
    const std::uint32_t* __restrict la = ra.lit + a;
    const std::uint32_t* __restrict lb = rb.lit + b;
    for (int i = 0; i < n; ++i) out[i] |= la[i] != lb[i] ? bit : 0;
    return;
  }
  for (int k = 0; k < words; ++k) {  // lit and visible on one side only
    const std::uint32_t* __restrict la = ra.lit + static_cast<std::size_t>(a) * words + k;
    const std::uint32_t* __restrict lb = rb.lit + static_cast<std::size_t>(b) * words + k;
    for (int i = 0; i < n; ++i) out[i] |= la[i * words] != lb[i * words] ? bit : 0;
  }
}

// lit[x * words] |= bit where spec[x] > 0, x < n: one slot's lit state into the entries' words.
// A function of its own: in the band's loop the stores through lit might have changed the
// captured width (int and unsigned alias), which was reloaded per pixel and kept it scalar.
void mark_lit(const float* __restrict spec, int n, int words, std::uint32_t bit,
              std::uint32_t* __restrict lit) {
  if (words == 1) {  // up to 32 slots: contiguous, vector code
    for (int x = 0; x < n; ++x) lit[x] |= spec[x] > 0.0f ? bit : 0u;
    return;
  }
  for (int x = 0; x < n; ++x) lit[x * words] |= spec[x] > 0.0f ? bit : 0u;
}

// refine[x] |= 1 where the displayed row mid's 4-neighbour Laplacian (rows up and down beside
// it) exceeds threshold in some channel, for padded entries 1 .. n. Pixel by pixel with its
// three channels side by side: one flag per pixel, no scatter into refine.
void mark_curvature(const float* __restrict up, const float* __restrict mid,
                    const float* __restrict down, int n, float threshold,
                    std::uint8_t* __restrict refine) {
  for (int x = 1; x <= n; ++x) {
    bool curved = false;
    for (int c = 0; c < 3; ++c) {
      const int i = 3 * x + c;
      const float laplacian = mid[i - 3] + mid[i + 3] + up[i] + down[i] - 4.0f * mid[i];
      curved |= std::fabs(laplacian) > threshold;
    }
    refine[x] |= curved ? 1 : 0;
  }
}

// refine[x] = whether padded entry x (1 .. n) of a row has an edge that differs: its own 4 flags
// (e), its left neighbour's kRight and, given the row above (up), that row's kDown at x,
// kDownRight at x - 1 and kDownLeft at x + 1. Raw pointers, restrict-qualified: byte stores may
// alias anything, and through vectors the compiler reloaded every pointer per pixel and kept
// the loops scalar.
void gather_edges(const std::uint8_t* __restrict e, const std::uint8_t* __restrict up, int n,
                  std::uint8_t* __restrict refine) {
  for (int x = 1; x <= n; ++x) refine[x] = e[x] | (e[x - 1] & kRight);
  if (up == nullptr) return;
  for (int x = 1; x <= n; ++x) {
    refine[x] |= (up[x] & kDown) | (up[x - 1] & kDownRight) | (up[x + 1] & kDownLeft);
  }
}

// Appends base + x - 1 for each padded entry x (1 .. n) with refine[x] != 0, ascending. Eight
// flags at a time: most of a row is not refined.
void collect_refined(const std::uint8_t* refine, int n, std::uint32_t base,
                     std::vector<std::uint32_t>& out) {
  const std::uint8_t* own = refine + 1;
  int x = 0;
  for (; x + 8 <= n; x += 8) {
    std::uint64_t word;
    std::memcpy(&word, own + x, sizeof word);
    if (word == 0) continue;
    for (int i = x; i < x + 8; ++i) {
      if (own[i] != 0) out.push_back(base + static_cast<std::uint32_t>(i));
    }
  }
  for (; x < n; ++x) {
    if (own[x] != 0) out.push_back(base + static_cast<std::uint32_t>(x));
  }
}

// One band's working memory, kept by each thread between calls: its padded rows and edge flags
// (a few hundred KB), so a pass allocates and faults in nothing per band. A band starts no
// parallel work, so a thread never holds two bands at once.
struct BandScratch {
  std::vector<std::int32_t> object;
  std::vector<std::uint32_t> lit;
  std::vector<float> shown;
  std::vector<std::uint8_t> edges, refine;
};

}  // namespace

std::vector<std::uint32_t> choose_refined_pixels(const SampleCache& cache, const CentreRing& ring,
                                                 const Image& linear, const RenderSettings& render,
                                                 int row_begin, int row_end) {
  std::vector<std::uint32_t> out;
  choose_refined_pixels(cache, ring, linear, render, row_begin, row_end, nullptr, out);
  return out;
}

// Band by band in one parallel pass: a band pads and displays the rows it looks at (its own and
// one on each side, each row by itself, so a row's displayed values do not depend on the
// banding), compares neighbours into edge flags and collects its refined pixels.
bool choose_refined_pixels(const SampleCache& cache, const CentreRing& ring, const Image& linear,
                           const RenderSettings& render, int row_begin, int row_end,
                           const std::atomic<bool>* cancel, std::vector<std::uint32_t>& out) {
  out.clear();
  const DisplayTransform display = display_transform(render);
  const int w = cache.width, h = cache.height;
  const int padded = w + 2;  // entries per padded row
  const SamplePlane& plane = cache.planes.at(0);
  const std::size_t slots = plane.lights.size();
  const int words = static_cast<int>((slots + 31) / 32);  // lit bits per entry
  if (ring.width != w || ring.height != h || ring.spec_weight.size() != slots) {
    throw std::invalid_argument("choose_refined_pixels: the centre ring is not the region's");
  }
  // Rows the rule reads: the region's, and the ring's above or below it.
  const auto exists = [&](int r) {
    return (r >= 0 && r < h) || (r == -1 && ring.top) || (r == h && ring.bottom);
  };
  const int rows = band_rows(w), chosen = row_end - row_begin;
  std::vector<std::vector<std::uint32_t>> bands(
      static_cast<std::size_t>(std::max(0, (chosen + rows - 1) / rows)));
  const bool chose = parallel_rows(w, chosen, cancel, [&](int r0, int r1) {
    std::vector<std::uint32_t>& band = bands[static_cast<std::size_t>(r0 / rows)];
    thread_local BandScratch scratch;
    const int y0 = row_begin + r0, y1 = row_begin + r1;
    // Padded rows y0 - 1 .. y1, row r at index r - s0.
    const int s0 = y0 - 1, count = y1 - y0 + 2;
    const auto entries = static_cast<std::size_t>(count) * padded;
    scratch.object.resize(entries);
    scratch.lit.assign(entries * static_cast<std::size_t>(words), 0u);
    scratch.shown.resize(entries * 3);
    const auto row = [&](int r) {
      const std::size_t at = static_cast<std::size_t>(r - s0) * padded;
      return PaddedRow{scratch.object.data() + at, scratch.lit.data() + at * words,
                       scratch.shown.data() + at * 3};
    };
    // The ring's points from index first on (count of them) into entries from e of row pr.
    const auto from_ring = [&](const PaddedRow& pr, int e, std::size_t first, int n) {
      std::copy_n(&ring.object[first], n, pr.object + e);
      for (std::size_t s = 0; s < slots; ++s) {
        mark_lit(&ring.spec_weight[s][first], n, words, 1u << (s % 32),
                 pr.lit + e * words + s / 32);
      }
      display_values(&ring.total[first].x, pr.shown + 3 * e, 3 * static_cast<std::size_t>(n),
                     display);
    };
    for (int r = s0; r <= y1; ++r) {
      if (!exists(r)) continue;
      const PaddedRow pr = row(r);
      if (r == -1) {
        from_ring(pr, 0, ring.above(-1), padded);
        continue;
      }
      if (r == h) {
        from_ring(pr, 0, ring.below(-1), padded);
        continue;
      }
      const std::size_t first = static_cast<std::size_t>(r) * w;
      std::copy_n(&plane.object[first], w, pr.object + 1);
      for (std::size_t s = 0; s < slots; ++s) {
        mark_lit(&plane.lights[s].spec_weight[first], w, words, 1u << (s % 32),
                 pr.lit + words + s / 32);
      }
      display_values(&linear.pixels[first].x, pr.shown + 3, 3 * static_cast<std::size_t>(w),
                     display);
      from_ring(pr, 0, ring.left(r), 1);
      from_ring(pr, w + 1, ring.right(r), 1);
    }
    // Edge flags of padded rows s0 .. y1 - 1 (those that exist).
    scratch.edges.assign(static_cast<std::size_t>(count) * padded, 0);
    const auto edges = [&](int r) {
      return &scratch.edges[static_cast<std::size_t>(r - s0) * padded];
    };
    for (int r = s0; r < y1; ++r) {
      if (!exists(r)) continue;
      std::uint8_t* e = edges(r);
      const PaddedRow a = row(r);
      mark_differences(a, 0, a, 1, padded - 1, words, kRight, e);
      if (!exists(r + 1)) continue;
      const PaddedRow b = row(r + 1);
      mark_differences(a, 0, b, 1, padded - 1, words, kDownRight, e);
      mark_differences(a, 0, b, 0, padded, words, kDown, e);
      mark_differences(a, 1, b, 0, padded - 1, words, kDownLeft, e + 1);
    }
    // A pixel is refined when one of its 8 edges differs (its own 4 flags, or the flag its left,
    // upper-left, upper and upper-right neighbours hold towards it) or where it curves.
    scratch.refine.resize(static_cast<std::size_t>(padded));
    std::uint8_t* const refine = scratch.refine.data();
    const float curvature = render.aa_threshold * kCurvatureShare;
    for (int y = y0; y < y1; ++y) {
      gather_edges(edges(y), exists(y - 1) ? edges(y - 1) : nullptr, w, refine);
      if (exists(y - 1) && exists(y + 1)) {
        mark_curvature(row(y - 1).shown, row(y).shown, row(y + 1).shown, w, curvature, refine);
      }
      collect_refined(refine, w, static_cast<std::uint32_t>(static_cast<std::size_t>(y) * w), band);
    }
  });
  if (!chose) return false;
  for (const auto& band : bands) out.insert(out.end(), band.begin(), band.end());
  return true;
}

}  // namespace gloss

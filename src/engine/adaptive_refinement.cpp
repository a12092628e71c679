#include "engine/adaptive_refinement.h"

#include <algorithm>
#include <cmath>

#include "display/display_transform.h"
#include "engine/parallel_loops.h"

namespace gloss {

namespace {
// Bits of a pixel's edge flags: whether it differs from its right, lower-right, lower and
// lower-left neighbour. Each pair of neighbours is compared once.
enum : std::uint8_t { kRight = 1, kDownRight = 2, kDown = 4, kDownLeft = 8 };

// out[i] |= bit where region pixels a + i and b + i differ by the rule, i < n. Plain loops over
// the cache's own arrays, so they run as vector code and allocate nothing.
void mark_differences(const SamplePlane& plane, const Image& total, std::size_t a, std::size_t b,
                      int n, float threshold, std::uint8_t bit, std::uint8_t* out) {
  const std::int32_t *oa = &plane.object[a], *ob = &plane.object[b];
  const float* ta = &total.pixels[a].x;
  const float* tb = &total.pixels[b].x;
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

// refine[x] |= 1 where the total's 4-neighbour Laplacian at (x, y) exceeds threshold in some
// channel (region rows y - 1 and y + 1 exist; columns 0 and w - 1 are border pixels anyway).
void mark_curvature(const Image& total, int y, int w, float threshold,
                    std::vector<std::uint8_t>& refine) {
  const float* up = &total.pixels[static_cast<std::size_t>(y - 1) * w].x;
  const float* mid = &total.pixels[static_cast<std::size_t>(y) * w].x;
  const float* down = &total.pixels[static_cast<std::size_t>(y + 1) * w].x;
  for (int i = 3; i < 3 * (w - 1); ++i) {  // channel by channel: plain vector code
    const float laplacian = mid[i - 3] + mid[i + 3] + up[i] + down[i] - 4.0f * mid[i];
    refine[static_cast<std::size_t>(i / 3)] |= std::fabs(laplacian) > threshold ? 1 : 0;
  }
}

// The total as the rule compares it: every channel displayed, in bands of rows.
Image displayed_total(const Image& linear, const DisplayTransform& display) {
  Image out(linear.width, linear.height);
  const int w = linear.width;
  parallel_rows(w, linear.height, nullptr, [&](int r0, int r1) {
    const std::size_t first = static_cast<std::size_t>(r0) * w * 3;
    display_values(&linear.pixels[0].x + first, &out.pixels[0].x + first,
                   static_cast<std::size_t>(r1 - r0) * w * 3, display);
  });
  return out;
}

}  // namespace

std::vector<std::uint32_t> choose_refined_pixels(const SampleCache& cache, const Image& linear,
                                                 const RenderSettings& render, int row_begin,
                                                 int row_end) {
  std::vector<std::uint32_t> out;
  choose_refined_pixels(cache, linear, render, row_begin, row_end, nullptr, out);
  return out;
}

bool choose_refined_pixels(const SampleCache& cache, const Image& linear,
                           const RenderSettings& render, int row_begin, int row_end,
                           const std::atomic<bool>* cancel, std::vector<std::uint32_t>& out) {
  out.clear();
  const float threshold = render.aa_threshold;
  const Image total = displayed_total(linear, display_transform(render));
  const int w = cache.width, h = cache.height;
  const SamplePlane& plane = cache.planes.at(0);
  // Edge flags of rows [k0, k1), the rows the chosen rows look at; index (y - k0) * w + x.
  const int k0 = std::max(0, row_begin - 1), k1 = std::min(h, row_end + 1);
  const auto at = [&](int x, int y) { return static_cast<std::size_t>(y - k0) * w + x; };
  const auto pixel = [&](int x, int y) { return static_cast<std::size_t>(y) * w + x; };
  std::vector<std::uint8_t> edges(static_cast<std::size_t>(k1 - k0) * w, 0);
  const bool marked = parallel_rows(w, k1 - k0, cancel, [&](int r0, int r1) {
    for (int y = k0 + r0; y < k0 + r1; ++y) {
      std::uint8_t* e = &edges[at(0, y)];
      auto mark = [&](int xa, int xb, int yb, int n, std::uint8_t bit, std::uint8_t* out) {
        mark_differences(plane, total, pixel(xa, y), pixel(xb, yb), n, threshold, bit, out);
      };
      mark(0, 1, y, w - 1, kRight, e);
      if (y + 1 >= k1) continue;  // the last row has no lower neighbours
      mark(0, 1, y + 1, w - 1, kDownRight, e);
      mark(0, 0, y + 1, w, kDown, e);
      mark(1, 0, y + 1, w - 1, kDownLeft, e + 1);
    }
  });
  // A pixel is refined when one of its 8 edges differs: its own 4 flags, or the flag its left,
  // upper-left, upper and upper-right neighbours hold towards it. The image border always:
  // beyond it lies no centre to compare with. Per band of rows its refined pixels, joined in
  // band order (ascending).
  const int rows = band_rows(w), chosen = row_end - row_begin;
  std::vector<std::vector<std::uint32_t>> bands(
      static_cast<std::size_t>(std::max(0, (chosen + rows - 1) / rows)));
  const bool chose =
      marked && parallel_rows(w, chosen, cancel, [&](int r0, int r1) {
        std::vector<std::uint32_t>& band = bands[static_cast<std::size_t>(r0 / rows)];
        std::vector<std::uint8_t> refine(static_cast<std::size_t>(w));
        for (int y = row_begin + r0; y < row_begin + r1; ++y) {
          const std::uint8_t* e = &edges[at(0, y)];
          for (int x = 0; x < w; ++x) refine[static_cast<std::size_t>(x)] = e[x];
          for (int x = 1; x < w; ++x) refine[static_cast<std::size_t>(x)] |= e[x - 1] & kRight;
          if (y > k0) {
            const std::uint8_t* up = &edges[at(0, y - 1)];
            for (int x = 0; x < w; ++x) refine[static_cast<std::size_t>(x)] |= up[x] & kDown;
            for (int x = 1; x < w; ++x)
              refine[static_cast<std::size_t>(x)] |= up[x - 1] & kDownRight;
            for (int x = 0; x + 1 < w; ++x)
              refine[static_cast<std::size_t>(x)] |= up[x + 1] & kDownLeft;
          }
          if (y > 0 && y + 1 < h) mark_curvature(total, y, w, threshold * kCurvatureShare, refine);
          const int row = cache.row0 + y;  // image row
          const bool border_row = row == 0 || row == cache.image_height - 1;
          const std::size_t base = static_cast<std::size_t>(y) * w;
          for (int x = 0; x < w; ++x) {
            if (border_row || x == 0 || x == w - 1 || refine[static_cast<std::size_t>(x)] != 0) {
              band.push_back(static_cast<std::uint32_t>(base + x));
            }
          }
        }
      });
  if (!chose) return false;
  for (const auto& band : bands) out.insert(out.end(), band.begin(), band.end());
  return true;
}

}  // namespace gloss

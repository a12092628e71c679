#include "engine/adaptive/centre_ring.h"

#include "engine/shade/pixel_factors.h"
#include "engine/trace/single_sample_pass.h"

namespace gloss {

namespace {
// Points per row of the strip the ring is traced in: whole packets, and rows short enough that
// a ring of a few thousand points is a handful of them.
constexpr int kStripWidth = 256;
}  // namespace

bool trace_centre_ring(const SampleCache& cache, const RenderContext& ctx, CentreRing& ring) {
  const int w = cache.width, h = cache.height;
  ring.width = w;
  ring.height = h;
  ring.top = cache.row0 == 0;
  ring.bottom = cache.row0 + h == cache.image_height;
  // Pixel centres, image coordinates, in CentreRing's order.
  std::vector<double> px, py;
  auto add = [&](int x, int row) {
    px.push_back(static_cast<double>(x) + 0.5);
    py.push_back(static_cast<double>(row) + 0.5);
  };
  for (int r = 0; r < h; ++r) {
    add(-1, cache.row0 + r);
    add(w, cache.row0 + r);
  }
  for (int x = -1; x <= w && ring.top; ++x) add(x, -1);
  for (int x = -1; x <= w && ring.bottom; ++x) add(x, cache.image_height);
  const std::size_t n = px.size();

  SampleCache strip;
  strip.width = kStripWidth;
  strip.height = static_cast<int>((n + kStripWidth - 1) / kStripWidth);
  PixelFactors factors;
  Image total;
  if (!trace_single_sample_at(strip, cache, px.data(), py.data(), n, ctx, factors, &total)) {
    return false;
  }
  const SamplePlane& plane = strip.planes[0];
  const auto points = static_cast<std::ptrdiff_t>(n);
  ring.object.assign(plane.object.begin(), plane.object.begin() + points);
  ring.total.assign(total.pixels.begin(), total.pixels.begin() + points);
  ring.spec_weight.clear();
  for (const LightFactorPlane& light : plane.lights) {
    ring.spec_weight.emplace_back(light.spec_weight.begin(), light.spec_weight.begin() + points);
  }
  return true;
}

}  // namespace gloss

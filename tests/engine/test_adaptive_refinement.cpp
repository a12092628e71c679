// Adaptive sampling: the refinement rule on images made by hand, refined pixels equal to uniform
// sampling's, the others to the centre sample, a placement independent of the renderer's bands.
#include "engine/adaptive/adaptive_refinement.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "engine/renderer.h"
#include "engine/trace/single_sample_pass.h"
#include "scene/memory/memory_estimate.h"
#include "support/image_compare.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

// A w x h centre cache of one object everywhere, no lights, and a grey total.
struct HandImage {
  SampleCache cache;
  Image total;
  RenderSettings render;  // its display transform: exposure 0, no tone curve, clamp
  HandImage(int w, int h, std::size_t lights) : total(w, h, glm::vec3(0.5f)) {
    cache.width = w;
    cache.height = h;
    cache.image_height = h;
    cache.planes.emplace_back();
    size_plane(cache.planes[0], cache.pixel_count(), lights);
    for (std::size_t i = 0; i < cache.pixel_count(); ++i) {
      cache.planes[0].object[i] = 0;
      for (LightFactorPlane& l : cache.planes[0].lights) l.spec_weight[i] = 1.0f;
    }
  }
  std::size_t at(int x, int y) const { return static_cast<std::size_t>(y) * cache.width + x; }
  // A centre ring that repeats the image's edge pixels (each point as its nearest pixel).
  CentreRing edge_ring() const {
    const int w = cache.width, h = cache.height;
    CentreRing ring;
    ring.width = w;
    ring.height = h;
    ring.top = ring.bottom = true;
    const std::vector<LightFactorPlane>& lights = cache.planes[0].lights;
    ring.spec_weight.resize(lights.size());
    auto add = [&](int x, int y) {
      const std::size_t p = at(std::clamp(x, 0, w - 1), std::clamp(y, 0, h - 1));
      ring.object.push_back(cache.planes[0].object[p]);
      ring.total.push_back(total.pixels[p]);
      for (std::size_t s = 0; s < lights.size(); ++s) {
        ring.spec_weight[s].push_back(lights[s].spec_weight[p]);
      }
    };
    for (int y = 0; y < h; ++y) {
      add(-1, y);
      add(w, y);
    }
    for (int x = -1; x <= w; ++x) add(x, -1);
    for (int x = -1; x <= w; ++x) add(x, h);
    return ring;
  }
  std::vector<std::uint32_t> all_refined(const CentreRing& ring) const {
    return choose_refined_pixels(cache, ring, total, render, 0, cache.height);
  }
  // The refined pixels off the image border, the ring repeating the edges.
  std::vector<std::uint32_t> refined(float threshold) {
    render.aa_threshold = threshold;
    std::vector<std::uint32_t> out;
    for (const std::uint32_t p : all_refined(edge_ring())) {
      const int x = static_cast<int>(p) % cache.width, y = static_cast<int>(p) / cache.width;
      if (x > 0 && y > 0 && x < cache.width - 1 && y < cache.height - 1) out.push_back(p);
    }
    return out;
  }
};

std::vector<std::uint32_t> pixel_list(std::initializer_list<std::pair<int, int>> xy, int w) {
  std::vector<std::uint32_t> out;
  for (const auto& p : xy) out.push_back(static_cast<std::uint32_t>(p.second * w + p.first));
  std::sort(out.begin(), out.end());
  return out;
}

// The border is compared with the centre ring beyond it, like any pixel with its neighbours.
TEST(AdaptiveRefinement, TheImageBorderIsComparedWithTheRing) {
  HandImage img(4, 3, 1);  // one object, lit everywhere, grey
  img.render.aa_threshold = 1.0f / 64.0f;
  CentreRing ring = img.edge_ring();
  EXPECT_TRUE(img.all_refined(ring).empty());  // nothing differs, the border included
  // Another object just left of row 1 (x = -1): its three neighbours in column 0.
  ring.object[ring.left(1)] = 1;
  EXPECT_EQ(img.all_refined(ring), pixel_list({{0, 0}, {0, 1}, {0, 2}}, 4));
  // In shadow just below (2, 2) instead (y = 3): its three neighbours in row 2.
  ring = img.edge_ring();
  ring.spec_weight[0][ring.below(2)] = 0.0f;
  EXPECT_EQ(img.all_refined(ring), pixel_list({{1, 2}, {2, 2}, {3, 2}}, 4));
  // Brighter above the corner (3, 0), by 0.2 (y = -1, x = 3): the corner's Laplacian 0.2 sees it.
  ring = img.edge_ring();
  ring.total[ring.above(3)] = glm::vec3(0.7f);
  EXPECT_EQ(img.all_refined(ring), pixel_list({{3, 0}}, 4));
  // The ring's corner points (-1, -1) and (4, 3) are diagonal neighbours of the image's corners.
  ring = img.edge_ring();
  ring.object[ring.above(-1)] = 2;
  ring.object[ring.below(4)] = 2;
  EXPECT_EQ(img.all_refined(ring), pixel_list({{0, 0}, {3, 2}}, 4));
}

TEST(AdaptiveRefinement, AnotherObjectRefinesItsWholeNeighbourhood) {
  HandImage img(7, 6, 0);
  img.cache.planes[0].object[img.at(3, 2)] = -1;  // one background pixel
  // Rows 1-3, columns 2-4: the pixel and its 8 neighbours, each seeing a different object.
  EXPECT_EQ(
      img.refined(0.1f),
      pixel_list({{2, 1}, {3, 1}, {4, 1}, {2, 2}, {3, 2}, {4, 2}, {2, 3}, {3, 3}, {4, 3}}, 7));
}

TEST(AdaptiveRefinement, AColourStepRefinesBothSidesOnlyAboveTheThreshold) {
  HandImage img(6, 4, 0);
  for (int y = 0; y < 4; ++y) {
    for (int x = 3; x < 6; ++x) img.total.pixels[img.at(x, y)] = glm::vec3(0.5f, 0.8f, 0.5f);
  }
  const std::vector<std::uint32_t> step = pixel_list({{2, 1}, {3, 1}, {2, 2}, {3, 2}}, 6);
  // The curvature test sees it: Laplacian +-0.3 on the two sides, above t / 10 for t < 3.
  EXPECT_EQ(img.refined(0.29f), step);
  EXPECT_EQ(img.refined(2.99f), step);
  EXPECT_TRUE(img.refined(3.01f).empty());
}

// A smooth gradient is not an edge, however steep: the centre of a linear ramp is its pixel's
// mean exactly, and its Laplacian is 0.
TEST(AdaptiveRefinement, ASteepSmoothGradientIsNotRefined) {
  HandImage img(8, 4, 0);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 8; ++x) {
      img.total.pixels[img.at(x, y)] = glm::vec3(0.1f + 0.1f * static_cast<float>(x));
    }
  }
  // Neighbours 0.1 apart, 6.4 times the default threshold of 1/64.
  EXPECT_TRUE(img.refined(1.0f / 64.0f).empty());
  // A kink in the ramp (it turns flat from column 4 on) curves: Laplacian -0.1 at column 4,
  // above 1/640, and 0 elsewhere.
  for (int y = 0; y < 4; ++y) {
    for (int x = 5; x < 8; ++x) img.total.pixels[img.at(x, y)] = glm::vec3(0.5f);
  }
  EXPECT_EQ(img.refined(1.0f / 64.0f), pixel_list({{4, 1}, {4, 2}}, 8));
}

// The rule compares what is displayed (docs/spec/shading.md, "Output encodings"): exposure, tone
// curve, clamp, encoding.
TEST(AdaptiveRefinement, ItComparesTheDisplayedValues) {
  HandImage img(5, 5, 0);
  img.total.pixels.assign(img.total.pixels.size(), glm::vec3(1.0f));
  img.total.pixels[img.at(2, 2)] = glm::vec3(1.5f);
  // The clamp shows 1 and 1.5 as the same white: no edge.
  EXPECT_TRUE(img.refined(0.2f).empty());
  // One stop down they show as 0.5 and 0.75: Laplacian -1 at the brighter pixel, 0.25 at its
  // four neighbours (above 0.2 / 10), 0 at the diagonal ones.
  const std::vector<std::uint32_t> cross = pixel_list({{2, 1}, {1, 2}, {2, 2}, {3, 2}, {2, 3}}, 5);
  img.render.exposure = -1.0f;
  EXPECT_EQ(img.refined(0.2f), cross);
  EXPECT_EQ(img.refined(3.0f), pixel_list({{2, 2}}, 5));  // 0.3: the brighter pixel only
  // Reinhard at exposure 0: 1 / 2 = 0.5 and 1.5 / 2.5 = 0.6: Laplacian 0.4 and 0.1.
  img.render.exposure = 0.0f;
  img.render.tone = ToneCurve::reinhard;
  EXPECT_EQ(img.refined(0.99f), cross);
  EXPECT_EQ(img.refined(1.01f), pixel_list({{2, 2}}, 5));
}

TEST(AdaptiveRefinement, TheSrgbEncodingMagnifiesDarkSteps) {
  HandImage img(6, 4, 0);
  img.total.pixels.assign(img.total.pixels.size(), glm::vec3(0.001f));
  for (int y = 0; y < 4; ++y) {
    for (int x = 3; x < 6; ++x) img.total.pixels[img.at(x, y)] = glm::vec3(0.004f);
  }
  // Linear: a step of 0.003, under 0.05, and a Laplacian of 0.003, under 0.005.
  EXPECT_TRUE(img.refined(0.05f).empty());
  // sRGB: 12.92 x 0.001 = 0.01292 against 1.055 x 0.004^(1/2.4) - 0.055 = 0.0508; the step of
  // 0.0379 stays under 0.05, its Laplacian does not.
  img.render.srgb = true;
  EXPECT_EQ(img.refined(0.05f), pixel_list({{2, 1}, {3, 1}, {2, 2}, {3, 2}}, 6));
}

TEST(AdaptiveRefinement, APeakBelowTheStepThresholdIsRefinedWhereItCurves) {
  HandImage img(6, 4, 0);
  img.total.pixels[img.at(2, 2)] = glm::vec3(0.5f, 0.51f, 0.5f);  // steps of 0.01 only
  EXPECT_TRUE(img.refined(0.5f).empty());  // Laplacian 0.04 at the peak, 0.01 beside it
  // t / 10 = 0.005: the peak and its side neighbours ((2, 3) is on the border: not counted).
  EXPECT_EQ(img.refined(0.05f), pixel_list({{2, 1}, {1, 2}, {2, 2}, {3, 2}}, 6));
  EXPECT_EQ(img.refined(0.125f), pixel_list({{2, 2}}, 6));  // 0.0125: the peak only
}

TEST(AdaptiveRefinement, AShadowEdgeRefinesEvenWhereTheColourHidesIt) {
  HandImage img(5, 3, 2);
  img.cache.planes[0].lights[1].spec_weight[img.at(3, 1)] = 0.0f;  // light 1 blocked at (3, 1)
  EXPECT_EQ(img.refined(1.0f), pixel_list({{2, 1}, {3, 1}}, 5));
}

using test::largest_channel_difference;

TEST(AdaptiveRefinement, RefinedPixelsEqualUniformSamplingAndTheRestTheCentre) {
  Scene scene = test::sphere_on_floor_scene();
  scene.render.spp = 16;
  std::vector<std::uint32_t> refined;
  RenderOptions options;
  options.refined = &refined;
  const TermImages adaptive = render(scene, options);
  scene.render.sampling = Sampling::uniform;
  const TermImages uniform = render(scene);
  scene.render.spp = 1;
  const TermImages centre = render(scene);
  // The sphere's silhouette and shadow are refined; most of the floor and background are not.
  const std::size_t pixels = adaptive.total.pixels.size();
  EXPECT_GT(refined.size(), pixels / 50);
  EXPECT_LT(refined.size(), pixels / 2);
  std::vector<bool> is_refined(pixels, false);
  for (const std::uint32_t p : refined) is_refined[p] = true;
  for (std::size_t i = 0; i < pixels; ++i) {
    const Image& expected = is_refined[i] ? uniform.total : centre.total;
    ASSERT_LE(largest_channel_difference(adaptive.total.pixels[i], expected.pixels[i]), 1e-6) << i;
    ASSERT_LE(
        largest_channel_difference(adaptive.specular.pixels[i],
                                   (is_refined[i] ? uniform.specular : centre.specular).pixels[i]),
        1e-6)
        << i;
  }
}

TEST(AdaptiveRefinement, PlacementDoesNotDependOnTheRenderersBands) {
  // 4096 spp over 160 columns: gloss-cli's renderer goes in bands of 11 rows.
  Scene scene = test::sphere_on_floor_scene();
  scene.render.width = 160;
  scene.render.height = 30;
  scene.render.spp = 4096;
  ASSERT_LT(sample_band_rows(160, 30, 4096, 1), 30);
  std::vector<std::uint32_t> banded;
  RenderOptions options;
  options.refined = &banded;
  render(scene, options);
  // The rule over the whole centre image at once.
  const EmbreeScene embree(scene);
  const RenderContext ctx = make_render_context(scene, embree);
  SampleCache cache = make_sample_cache(scene, 160, 30, 1);
  PixelFactors factors;
  Image total;
  ASSERT_TRUE(trace_single_sample(cache, ctx, factors, &total));
  CentreRing ring;
  ASSERT_TRUE(trace_centre_ring(cache, ctx, ring));
  EXPECT_EQ(banded, choose_refined_pixels(cache, ring, total, scene.render, 0, 30));
}

}  // namespace
}  // namespace gloss

// The reference path given adaptive sampling's placement (ReferenceOptions::refined) agrees with
// the fast renderer's adaptive image: one spec, every path.
#include <algorithm>

#include <gtest/gtest.h>

#include "engine/renderer.h"
#include "reference/reference_renderer.h"
#include "support/image_compare.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

using test::largest_channel_difference;

TEST(AdaptiveReference, ReferencePathAgreesGivenTheSamePlacement) {
  Scene scene = test::sphere_on_floor_scene();
  scene.render.spp = 16;
  std::vector<std::uint32_t> refined;
  RenderOptions options;
  options.refined = &refined;
  const TermImages fast = render(scene, options);
  std::vector<std::uint8_t> mask(fast.total.pixels.size(), 0);
  for (const std::uint32_t p : refined) mask[p] = 1;
  ReferenceOptions reference;
  reference.refined = &mask;
  std::vector<std::uint8_t> edges;
  reference.edges = &edges;
  const TermImages exact = render_reference<double>(scene, reference);
  // The spec's tolerance on interior pixels (1e-4 at alpha <= 1000); flips at edges allowed.
  std::size_t off = 0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (edges[i] != 0) continue;
    if (largest_channel_difference(fast.total.pixels[i], exact.total.pixels[i]) > 1e-4) ++off;
  }
  EXPECT_EQ(off, 0u);
}

TEST(AdaptiveReference, MaskMarksWhichPixelsTakeEverySample) {
  // Without refined pixels the reference is the centre image; with all of them, uniform.
  Scene scene = test::sphere_on_floor_scene();
  scene.render.spp = 4;
  const std::size_t pixels = 80 * 60;
  std::vector<std::uint8_t> none(pixels, 0), all(pixels, 1);
  ReferenceOptions options;
  options.refined = &none;
  const TermImages centre = render_reference<double>(scene, options);
  options.refined = &all;
  const TermImages uniform = render_reference<double>(scene, options);
  const TermImages plain = render_reference<double>(scene);
  scene.render.spp = 1;
  const TermImages one = render_reference<double>(scene);
  EXPECT_EQ(centre.total.pixels, one.total.pixels);
  EXPECT_EQ(uniform.total.pixels, plain.total.pixels);
  EXPECT_NE(uniform.total.pixels, one.total.pixels);
}

}  // namespace
}  // namespace gloss

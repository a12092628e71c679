// The A/B view's physical-reference side on its worker (reference_preview.h): its frame is the
// reference path's image, a same document is no new generation, and quitting or editing mid-pass
// drops the pass.
#include "editor/model/view/reference_preview.h"

#include <gtest/gtest.h>

#include "reference/reference_renderer.h"
#include "support/test_scene.h"

namespace gloss {
namespace {

Scene gold_scene(int width, int height) {
  Scene scene = test::two_sphere_scene();
  PhysicalReference gold;
  gold.roughness = 0.25f;
  scene.materials[0].reference = gold;
  scene.render.width = width;
  scene.render.height = height;
  scene.render.spp = 4;  // the preview renders one sample per pixel whatever the document says
  return scene;
}

TEST(ReferencePreview, PublishesTheReferencePathsImage) {
  const Scene scene = gold_scene(48, 36);
  ReferencePreview preview;
  EXPECT_EQ(preview.latest(), nullptr);
  const std::uint64_t g = preview.set_scene(scene);
  ASSERT_TRUE(preview.wait_converged(60000));
  const auto frame = preview.latest();
  ASSERT_NE(frame, nullptr);
  EXPECT_EQ(frame->info.generation, g);
  EXPECT_TRUE(frame->info.converged);
  ReferenceOptions options;
  options.physical = true;
  options.spp = 1;
  const TermImages expected = render_reference<double>(scene, options);
  EXPECT_EQ(frame->images.total.pixels, expected.total.pixels);
  EXPECT_EQ(frame->images.specular.pixels, expected.specular.pixels);
  // The same document again is not a new generation; an edit is.
  EXPECT_EQ(preview.set_scene(scene), g);
  Scene rougher = scene;
  rougher.materials[0].reference->roughness = 0.6f;
  const std::uint64_t g2 = preview.set_scene(rougher);
  EXPECT_GT(g2, g);
  ASSERT_TRUE(preview.wait_converged(60000));
  EXPECT_EQ(preview.latest()->info.generation, g2);
  EXPECT_NE(preview.latest()->images.total.pixels, expected.total.pixels);
}

// Destroying it while a pass runs cancels the pass (the flag is read per row) and joins; a
// pass cancelled by a newer document publishes nothing of the older one.
TEST(ReferencePreview, QuittingOrEditingMidPassDropsThePass) {
  {
    ReferencePreview quitting;
    quitting.set_scene(gold_scene(800, 600));
  }
  ReferencePreview preview;
  preview.set_scene(gold_scene(800, 600));
  const std::uint64_t last = preview.set_scene(gold_scene(40, 30));
  ASSERT_TRUE(preview.wait_converged(60000));
  EXPECT_EQ(preview.latest()->info.generation, last);
  EXPECT_EQ(preview.latest()->info.width, 40);
}

}  // namespace
}  // namespace gloss

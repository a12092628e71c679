// The reference path leaves hidden objects out as the fast renderer does: the image of a scene
// with a hidden sphere is the image of the scene without it.
#include <cstring>

#include <gtest/gtest.h>

#include "reference/reference_renderer.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

TEST(HiddenReference, AHiddenSphereIsNeitherSeenNorCastsAShadow) {
  Scene hidden = test::shadowing_sphere_scene();
  hidden.objects[0].hidden = true;
  Scene without = test::shadowing_sphere_scene();
  without.objects.erase(without.objects.begin());
  const Image a = render_reference<double>(hidden).total;
  const Image b = render_reference<double>(without).total;
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)), 0);
  // The lit floor at the centre: 0.2 x 0.2 + 0.5 (scene_fixtures.h).
  EXPECT_NEAR(a.pixels[16 * 33 + 16].y, 0.54f, 1e-6f);
  const Image shown = render_reference<double>(test::shadowing_sphere_scene()).total;
  EXPECT_GT(shown.pixels[16 * 33 + 16].x, 2.0f * shown.pixels[16 * 33 + 16].y);  // the red ball
}

}  // namespace
}  // namespace gloss

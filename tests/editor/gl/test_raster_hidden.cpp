// The raster path leaves hidden objects out, from the image and from the shadow maps: its image
// of a scene with a hidden sphere is its image of the scene without it.
#include <cstring>

#include <gtest/gtest.h>

#include "editor/gl/egl_context.h"
#include "editor/gl/raster/raster_renderer.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

TEST(RasterHidden, AHiddenSphereIsNeitherDrawnNorInTheShadowMaps) {
  test::EglContext context;
  if (!context.ok()) GTEST_SKIP() << "no EGL surfaceless GL: " << context.error();
  RasterRenderer renderer;
  const RasterSettings settings;
  Scene hidden = test::shadowing_sphere_scene();
  hidden.objects[0].hidden = true;
  Scene without = test::shadowing_sphere_scene();
  without.objects.erase(without.objects.begin());
  const Image a = renderer.render(hidden, settings, false)->images.total;
  const Image b = renderer.render(without, settings, false)->images.total;
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)), 0);
  EXPECT_NEAR(a.pixels[16 * 33 + 16].y, 0.54f, 1e-4f);  // the lit floor (scene_fixtures.h)
  // Shown, the sphere is there and its shadow too: the floor beside the ball's disc is darker.
  const Image shown =
      renderer.render(test::shadowing_sphere_scene(), settings, false)->images.total;
  EXPECT_GT(shown.pixels[16 * 33 + 16].x, 2.0f * shown.pixels[16 * 33 + 16].y);
}

}  // namespace
}  // namespace gloss

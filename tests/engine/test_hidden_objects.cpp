// A hidden object (`"hidden": true`) is not rendered and casts no shadow: the image equals the
// image of the scene without it, and the floor under it is lit as a person computes it.
#include <cstring>

#include <gtest/gtest.h>

#include "engine/pick.h"
#include "engine/render_plan.h"
#include "engine/renderer.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

bool identical(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

const glm::vec3& centre(const Image& image) {
  return image.pixels[static_cast<std::size_t>(16 * image.width + 16)];
}

TEST(HiddenObjects, AHiddenSphereIsNeitherSeenNorCastsAShadow) {
  Scene shown = test::shadowing_sphere_scene();
  Scene hidden = shown;
  hidden.objects[0].hidden = true;
  Scene without = shown;
  without.objects.erase(without.objects.begin());

  const TermImages with_sphere = render(shown);
  const TermImages with_hidden = render(hidden);
  // The centre sees the sphere's top when it is there: its red diffuse, not the floor's grey.
  EXPECT_GT(centre(with_sphere.total).x, 2.0f * centre(with_sphere.total).y);
  // Hidden, it sees the lit floor: 0.2 x 0.2 + 0.5 x 1 x (N.L = 1) = 0.54 in every channel.
  EXPECT_NEAR(centre(with_hidden.total).x, 0.54f, 1e-6f);
  EXPECT_NEAR(centre(with_hidden.total).z, 0.54f, 1e-6f);
  // And everywhere it is the scene without the sphere, bit for bit, with and without the plan.
  EXPECT_TRUE(identical(with_hidden.total, render(without).total));
  RenderOptions full;
  full.full_plan = true;
  EXPECT_TRUE(identical(render(hidden, full).total, render(without, full).total));
  EXPECT_TRUE(identical(render(hidden, full).diffuse, render(without, full).diffuse));
}

TEST(HiddenObjects, TheShadowOfAVisibleSphereIsThereAndGoesWhenItIsHidden) {
  // The light moves to (0, 4, -4): the segment from the centre's floor point (0, 0, 0) to it
  // passes (0, 1, -1), where the sphere now sits, out of the camera's centre ray (it spans z
  // -1.5..-0.5). Shadowed, the centre is ambient alone: 0.2 x 0.2 = 0.04. Lit (hidden), N.L is
  // cos 45 degrees: 0.04 + 0.5 x 0.70711 = 0.39355.
  Scene scene = test::shadowing_sphere_scene();
  scene.lights[0].position = {0, 4, -4};
  scene.objects[0].params.center = scene.objects[0].center = {0, 1, -1};
  scene.objects[0].transform.pivot = scene.objects[0].center;
  EXPECT_NEAR(centre(render(scene).total).x, 0.04f, 1e-6f);
  scene.objects[0].hidden = true;
  EXPECT_NEAR(centre(render(scene).total).x, 0.04f + 0.5f * 0.70710678f, 1e-5f);
}

TEST(HiddenObjects, AHiddenObjectCannotBePickedAndLeavesThePlan) {
  Scene scene = test::shadowing_sphere_scene();
  EXPECT_EQ(pick_object(scene, 33, 33, 16.5f, 16.5f), 0);
  EXPECT_TRUE(make_render_plan(scene).shadow_rays);  // two objects: one may shadow the other
  scene.objects[0].hidden = true;
  EXPECT_EQ(pick_object(scene, 33, 33, 16.5f, 16.5f), 1);  // the floor behind it
  EXPECT_FALSE(make_render_plan(scene).shadow_rays);       // one convex quad casts none
  scene.objects[1].hidden = true;
  EXPECT_EQ(pick_object(scene, 33, 33, 16.5f, 16.5f), -1);
}

}  // namespace
}  // namespace gloss

// The render plan computes only what the scene needs, and skipping never changes a pixel.
#include "engine/render_plan.h"

#include <cstring>

#include <gtest/gtest.h>

#include "engine/renderer.h"
#include "io/scene/scene_loader.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

bool identical(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

void expect_planned_equals_unplanned(const Scene& scene) {
  RenderOptions full;
  full.full_plan = true;
  const TermImages planned = render(scene), unplanned = render(scene, full);
  EXPECT_TRUE(identical(planned.total, unplanned.total));
  EXPECT_TRUE(identical(planned.emissive, unplanned.emissive));
  EXPECT_TRUE(identical(planned.ambient, unplanned.ambient));
  EXPECT_TRUE(identical(planned.diffuse, unplanned.diffuse));
  EXPECT_TRUE(identical(planned.specular, unplanned.specular));
}

TEST(RenderPlan, LoneConvexSphereNeedsNoShadowRays) {
  const Scene scene = test::head_on_sphere_scene();
  ASSERT_TRUE(scene.render.shadows);
  EXPECT_FALSE(make_render_plan(scene).shadow_rays);
  EXPECT_TRUE(make_render_plan(scene, true).shadow_rays);
}

// From inside, the sphere's far wall hides a light outside: the eye at 0.5 of the unit radius
// needs shadow rays, and the plan's image must still equal the unplanned one there.
TEST(RenderPlan, LoneSphereSeenFromInsideNeedsShadowRays) {
  Scene scene = test::head_on_sphere_scene();
  scene.camera.eye = {0, 0, 0.5f};
  EXPECT_TRUE(make_render_plan(scene).shadow_rays);
  scene.camera.eye = {0, 0, 1.01f};  // just outside: nothing can be hidden
  EXPECT_FALSE(make_render_plan(scene).shadow_rays);
  scene.camera.eye = {0, 0, 0.5f};
  scene.lights[0].position = {0, 3, -1};
  expect_planned_equals_unplanned(scene);
}

TEST(RenderPlan, SecondObjectOrShadowsOffDecideShadowRays) {
  Scene scene = test::head_on_sphere_scene();
  test::add_sphere(scene, {2, 0, 0}, 0.5f, 0);
  EXPECT_TRUE(make_render_plan(scene).shadow_rays);
  scene.render.shadows = false;
  EXPECT_FALSE(make_render_plan(scene).shadow_rays);
}

TEST(RenderPlan, BlackLightsAndZeroTermsAreSkipped) {
  Scene scene = test::head_on_sphere_scene();
  scene.lights.push_back(test::make_light({1, 1, 1}, glm::vec3(0.0f), glm::vec3(0.0f)));
  RenderPlan plan = make_render_plan(scene);
  ASSERT_EQ(plan.lights.size(), 1u);
  EXPECT_EQ(plan.lights[0], 0);
  EXPECT_FALSE(plan.unit_attenuation[0]);  // (1, 0.1, 0.01)
  scene.materials[0].specular = glm::vec3(0.0f);
  scene.materials[0].emission = glm::vec3(0.0f);
  plan = make_render_plan(scene);
  EXPECT_FALSE(plan.specular);
  EXPECT_FALSE(plan.emissive);
  EXPECT_TRUE(plan.diffuse);
  EXPECT_TRUE(plan.ambient);
}

TEST(RenderPlan, UnitAttenuationIsRecognised) {
  Scene scene = test::head_on_sphere_scene();
  scene.lights[0].attenuation = {1, 0, 0};
  EXPECT_TRUE(make_render_plan(scene).unit_attenuation[0]);
  EXPECT_FALSE(make_render_plan(scene, true).unit_attenuation[0]);
}

TEST(RenderPlan, PlannedImageEqualsUnplannedOnLoneSphere) {
  expect_planned_equals_unplanned(test::head_on_sphere_scene());
}

TEST(RenderPlan, PlannedImageEqualsUnplannedWithBlackLightAndDarkTerms) {
  Scene scene = test::head_on_sphere_scene();
  scene.lights.push_back(test::make_light({-3, 2, 4}, glm::vec3(0.0f), glm::vec3(0.0f)));
  scene.lights[0].attenuation = {1, 0, 0};
  scene.materials[0].specular = glm::vec3(0.0f);
  scene.render.spp = 4;
  expect_planned_equals_unplanned(scene);
}

TEST(RenderPlan, PlannedImageEqualsUnplannedOnShippedScenes) {
  for (const char* name : {"spheres.json", "cornell.json"}) {
    Scene scene = load_scene(std::string(GLOSS_ASSETS_DIR) + "/scenes/" + name);
    scene.render.width = 96;
    scene.render.height = 72;
    scene.render.spp = 2;
    SCOPED_TRACE(name);
    expect_planned_equals_unplanned(scene);
  }
}

}  // namespace
}  // namespace gloss

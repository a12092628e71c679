// The environment light through the renderers (docs/spec/shading.md, "Environment light"): a
// uniform environment gives exactly kd L + ks L on the fast path and the exact path, any alpha,
// both models; a map's middle column is straight ahead and a positive rotation turns it
// counter-clockwise seen from above (a planted opposite turn fails); the fast path and the
// progressive estimates against the reference; numerical edges (a sun of 1e6, a black map, a
// 1 x 1 map, alpha 0 to 1e6).
#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/renderer.h"
#include "reference/reference_renderer.h"
#include "shading/environment.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

std::shared_ptr<const EnvironmentMap> constant_map(int w, int h, const glm::vec3& l) {
  auto map = std::make_shared<EnvironmentMap>();
  map->radiance = Image(w, h, l);
  return map;
}

// One sphere in an environment, no lights, no ambient; kd and ks given.
Scene sphere_in(std::shared_ptr<const EnvironmentMap> map, const glm::vec3& kd, const glm::vec3& ks,
                float alpha) {
  Scene scene;
  scene.camera.eye = {0.0f, 0.5f, 4.0f};
  scene.ambient = glm::vec3(0.0f);
  const int m = test::add_material(
      scene, "m", test::make_material(glm::vec3(0.0f), kd, ks, glm::vec3(0.0f), alpha));
  test::add_sphere(scene, {0, 0, 0}, 1.0f, m);
  scene.environment.map = std::move(map);
  scene.environment.file = "test";
  scene.render.width = 40;
  scene.render.height = 30;
  scene.render.shadows = false;
  return scene;
}

double largest_off(const Image& image, const glm::vec3& want, const Image& coverage) {
  double off = 0.0;
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    if (coverage.pixels[i] == glm::vec3(0.0f)) continue;  // missed
    off = std::max(off, double(glm::length(image.pixels[i] - want)));
  }
  return off;
}

TEST(EnvironmentRender, AUniformEnvironmentGivesExactlyKdLPlusKsL) {
  const glm::vec3 l(0.7f, 0.5f, 0.3f), kd(0.2f, 0.4f, 0.6f), ks(0.5f, 0.3f, 0.1f);
  for (const auto& map : {constant_map(1, 1, l), constant_map(64, 32, l)}) {
    for (ShadingModel model : {ShadingModel::phong, ShadingModel::blinn_phong}) {
      for (float alpha : {0.0f, 1.0f, 7.5f, 51.2f, 1000.0f, 1e6f}) {
        Scene scene = sphere_in(map, kd, ks, alpha);
        scene.render.model = model;
        scene.environment.intensity = 2.0f;
        for (int samples : {0, 16}) {  // the fast path alone, then the exact path
          scene.render.env_samples = samples;
          const TermImages images = render(scene);
          const double d = largest_off(images.diffuse, kd * l * 2.0f, images.diffuse);
          const double s = largest_off(images.specular, ks * l * 2.0f, images.diffuse);
          EXPECT_LT(d, 2e-6) << to_string(model) << " alpha " << alpha << " samples " << samples;
          EXPECT_LT(s, 2e-6) << to_string(model) << " alpha " << alpha << " samples " << samples;
        }
      }
    }
  }
}

// A map dark but for one bright column of texels at u = 0.75 (map +x) and a camera looking down
// -z: the column shows at the image's right edge with rotation 0, straight ahead with rotation
// 90 (the map turned counter-clockwise seen from above, +x to -z).
TEST(EnvironmentRender, TheMapsFrameAndRotationAreTheContracts) {
  auto map = std::make_shared<EnvironmentMap>();
  map->radiance = Image(64, 32, glm::vec3(0.01f));
  for (int j = 0; j < 32; ++j) map->radiance.at(48, j) = glm::vec3(1.0f);  // u = (48.5) / 64
  Scene scene;
  scene.camera.eye = {0, 0, 0};
  scene.camera.target = {0, 0, -1};
  scene.camera.fov_y = 10.0f;
  scene.environment.map = map;
  scene.environment.file = "test";
  scene.render.width = scene.render.height = 9;
  auto centre = [&](float rotation) {
    Scene s = scene;
    s.environment.rotation = rotation;
    return render(s).total.at(4, 4).x;
  };
  // Column 48 is at u 0.7578, phi 0.5 pi + 0.049: 2.8 degrees right of +x.
  const float turned = 90.0f + 2.8125f;
  EXPECT_GT(centre(turned), 0.9f);
  EXPECT_LT(centre(0.0f), 0.02f);
  // Planted: the map turned the other way puts the column behind the camera.
  EXPECT_LT(centre(-turned), 0.02f);
  // And the reference path sees the same sky.
  Scene s = scene;
  s.environment.rotation = turned;
  ReferenceOptions one;
  one.spp = 1;
  EXPECT_GT(render_reference<double>(s, one).total.at(4, 4).x, 0.9f);
}

TEST(EnvironmentRender, NumericalEdgesGiveFiniteImages) {
  // A sun of 1e6 on black, a black map, a 1 x 1 map; alpha 0 to 1e6; shadows on and off.
  auto sun = std::make_shared<EnvironmentMap>();
  sun->radiance = Image(32, 16, glm::vec3(0.0f));
  sun->radiance.at(20, 5) = glm::vec3(1e6f);
  const std::shared_ptr<const EnvironmentMap> maps[] = {sun, constant_map(16, 8, glm::vec3(0.0f)),
                                                        constant_map(1, 1, glm::vec3(3.0f))};
  for (const auto& map : maps) {
    for (float alpha : {0.0f, 1.0f, 1e6f}) {
      Scene scene = sphere_in(map, glm::vec3(0.5f), glm::vec3(0.5f), alpha);
      test::add_quad(scene, {-3, -1, 3}, {3, -1, 3}, {3, -1, -3}, {-3, -1, -3}, 0);
      scene.render.shadows = true;
      scene.render.env_samples = 16;
      scene.render.width = 16;
      scene.render.height = 12;
      ReferenceOptions few;
      few.environment.steps = 32;
      for (const TermImages& images : {render(scene), render_reference<double>(scene, few)}) {
        for (const glm::vec3& c : images.total.pixels) {
          ASSERT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z)) << alpha;
        }
      }
    }
  }
}

}  // namespace
}  // namespace gloss

// The one-shot renderer against values computed by hand from docs/spec/shading.md.
#include "engine/renderer.h"

#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "scene/camera.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

using test::head_on_sphere_scene;

void expect_rgb(const glm::vec3& got, double r, double g, double b, double tol = 1e-5) {
  EXPECT_NEAR(got.x, r, tol);
  EXPECT_NEAR(got.y, g, tol);
  EXPECT_NEAR(got.z, b, tol);
}

// Centre pixel of the head-on sphere: p = (0,0,1), n = v = (0,0,1). Light at (0,3,5):
// P - p = (0,3,4), d = 5, l = (0,0.6,0.8), ndl = 0.8, att = 1/(1 + 0.1*5 + 0.01*25) = 1/1.75.
// Phong: R = 2*0.8*n - l = (0,-0.6,0.8), c = 0.8, c^10 = 0.1073741824.
// Blinn: h = (0,0.6,1.8)/sqrt(3.6), c = 1.8/sqrt(3.6) = sqrt(0.9), c^10 = 0.9^5 = 0.59049.
TEST(Renderer, HeadOnSphereCentrePixelMatchesHandComputation) {
  const Scene scene = head_on_sphere_scene();
  const TermImages img = render(scene);
  const double att = 1.0 / 1.75;
  expect_rgb(img.emissive.at(50, 50), 0.01, 0.0, 0.0);
  // ka * (A + La) = ka * 0.3
  expect_rgb(img.ambient.at(50, 50), 0.03, 0.06, 0.09);
  // kd * Ld * ndl * att
  expect_rgb(img.diffuse.at(50, 50), 0.5 * 0.8 * att, 0.4 * 0.8 * att, 0.3 * 0.8 * att);
  // ks * Ls * c^10 * att, Ls = (1, 0.5, 0.25)
  const double s = 0.8 * 0.1073741824 * att;
  expect_rgb(img.specular.at(50, 50), s, s * 0.5, s * 0.25);
  const glm::vec3 sum = img.emissive.at(50, 50) + img.ambient.at(50, 50) + img.diffuse.at(50, 50) +
                        img.specular.at(50, 50);
  expect_rgb(img.total.at(50, 50), sum.x, sum.y, sum.z, 1e-6);
}

TEST(Renderer, BlinnPhongCentrePixelMatchesHandComputation) {
  Scene scene = head_on_sphere_scene();
  scene.render.model = ShadingModel::blinn_phong;
  const TermImages img = render(scene);
  const double s = 0.8 * 0.59049 / 1.75;
  expect_rgb(img.specular.at(50, 50), s, s * 0.5, s * 0.25);
}

TEST(Renderer, EnergyNormalisationScalesSpecularByTheLobeFactor) {
  Scene scene = head_on_sphere_scene();
  scene.render.energy_normalize = true;
  const TermImages img = render(scene);
  const double pi = 3.14159265358979323846;
  const double s = 0.8 * 0.1073741824 / 1.75 * (10.0 + 2.0) / (2.0 * pi);
  expect_rgb(img.specular.at(50, 50), s, s * 0.5, s * 0.25);
}

TEST(Renderer, MissedRaysGiveBackgroundInTotalAndZeroInTerms) {
  Scene scene = head_on_sphere_scene();
  scene.background = {0.25f, 0.5f, 0.75f};
  const TermImages img = render(scene);
  expect_rgb(img.total.at(0, 0), 0.25, 0.5, 0.75, 0.0);
  for (const Image* term : {&img.emissive, &img.ambient, &img.diffuse, &img.specular}) {
    expect_rgb(term->at(0, 0), 0, 0, 0, 0.0);
  }
}

TEST(Renderer, TermsSumToTotalEverywhereWithAntiAliasing) {
  Scene scene = head_on_sphere_scene();
  scene.render.spp = 9;
  const TermImages img = render(scene);
  double worst = 0;
  for (std::size_t i = 0; i < img.total.pixels.size(); ++i) {
    const glm::vec3 sum = img.emissive.pixels[i] + img.ambient.pixels[i] + img.diffuse.pixels[i] +
                          img.specular.pixels[i];
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(double(sum[c] - img.total.pixels[i][c])));
  }
  EXPECT_LT(worst, 1e-6);  // background is black here, so misses add nothing
}

TEST(Renderer, AttenuationFollowsInverseSquareCoefficients) {
  Scene scene = head_on_sphere_scene();
  scene.lights[0].attenuation = {0.0f, 0.0f, 1.0f};  // att = 1/d^2 = 1/25
  const TermImages img = render(scene);
  expect_rgb(img.diffuse.at(50, 50), 0.5 * 0.8 / 25, 0.4 * 0.8 / 25, 0.3 * 0.8 / 25);
}

// A floor quad at y = -1 under a sphere of radius 0.5 at (0, 0, 0), light straight above at
// (0, 5, 0): the floor point (0, -1, 0) lies on the segment's shadow axis.
TEST(Renderer, FloorUnderSphereIsInShadow) {
  Scene scene;
  scene.camera.eye = {0, 4, 6};
  scene.camera.target = {0, -1, 0};
  scene.camera.fov_y = 30;
  scene.ambient = glm::vec3(0.2f);
  const int m = test::add_material(
      scene, "grey",
      test::make_material(glm::vec3(0.5f), glm::vec3(0.5f), glm::vec3(0.0f), glm::vec3(0.0f), 1));
  test::add_quad(scene, {-3, -1, 3}, {3, -1, 3}, {3, -1, -3}, {-3, -1, -3}, m);
  test::add_sphere(scene, {0, 0, 0}, 0.5f, m);
  scene.lights.push_back(test::make_light({0, 5, 0}));
  scene.render.width = 64;
  scene.render.height = 48;
  // Project the floor point (0, -1, 0) and a lit floor point (2, -1, 2) to pixels.
  const CameraFrame frame = make_camera_frame(scene.camera, 64, 48);
  auto project = [&](glm::vec3 p, int& x, int& y) {
    const glm::vec3 d = p - frame.eye;
    const float z = glm::dot(d, frame.forward);
    const float sx = glm::dot(d, frame.right) / z / frame.scale_x;
    const float sy = glm::dot(d, frame.up) / z / frame.scale_y;
    x = static_cast<int>(std::floor((sx + 1) * 0.5f * 64));
    y = static_cast<int>(std::floor((1 - sy) * 0.5f * 48));
  };
  // The sphere hides (0,-1,0) from this camera; take a shadowed point in front of it instead.
  // The shadow cone has sin(theta) = 0.5/5, so its disc on the floor (6 below the light) has
  // radius 6 tan(theta) = 0.603; (0.3, -1, 0.35) is 0.461 from the axis, and the camera ray to
  // it passes 1.02 from the sphere's centre (not hidden).
  int sx, sy, lx, ly;
  project({0.3f, -1.0f, 0.35f}, sx, sy);
  project({2.0f, -1.0f, 2.0f}, lx, ly);
  const TermImages img = render(scene);
  expect_rgb(img.diffuse.at(sx, sy), 0, 0, 0, 0.0);
  expect_rgb(img.ambient.at(sx, sy), 0.5 * 0.2, 0.5 * 0.2, 0.5 * 0.2);
  EXPECT_GT(img.diffuse.at(lx, ly).x, 0.05f);
  scene.render.shadows = false;
  const TermImages unshadowed = render(scene);
  EXPECT_GT(unshadowed.diffuse.at(sx, sy).x, 0.05f);
}

// A quad in the plane z = 0 wound to face -z, seen from +z: two-sided shading flips its normal
// towards the viewer. Light at the eye (0,0,5): at the centre ndl = 1, att = 1.
TEST(Renderer, TwoSidedQuadSeenFromBehindIsLit) {
  Scene scene;
  scene.camera.eye = {0, 0, 5};
  scene.camera.fov_y = 40;
  scene.ambient = glm::vec3(0.0f);
  const int m = test::add_material(scene, "m",
                                   test::make_material(glm::vec3(0.0f), {0.6f, 0.4f, 0.2f},
                                                       glm::vec3(0.0f), glm::vec3(0.0f), 1));
  // Corners clockwise seen from +z: cross(b - a, c - a) points to -z.
  test::add_quad(scene, {-1, -1, 0}, {-1, 1, 0}, {1, 1, 0}, {1, -1, 0}, m);
  scene.lights.push_back(test::make_light({0, 0, 5}));
  scene.render.width = scene.render.height = 21;
  const TermImages img = render(scene);
  expect_rgb(img.diffuse.at(10, 10), 0.6, 0.4, 0.2);
}

// Both models peak where n bisects l and v. Floor z = 0 (facing +z), eye (0,-4,3) looking at the
// origin, light (0,2,1): the mirror point is where the line from the eye to the mirrored light
// (0,2,-1) crosses z = 0: s = 3/4, y = -4 + 0.75 * 6 = 0.5, so (0, 0.5, 0).
TEST(Renderer, PhongAndBlinnHighlightsPeakAtTheMirrorPoint) {
  Scene scene;
  scene.camera.eye = {0, -4, 3};
  scene.camera.target = {0, 0, 0};
  scene.camera.up = {0, 0, 1};
  scene.camera.fov_y = 50;
  const int m = test::add_material(
      scene, "m",
      test::make_material(glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(1.0f), glm::vec3(0.0f), 200));
  test::add_quad(scene, {-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, m);
  scene.lights.push_back(test::make_light({0, 2, 1}));
  scene.render.width = 161;
  scene.render.height = 121;
  const CameraFrame frame = make_camera_frame(scene.camera, 161, 121);
  const glm::vec3 d = glm::vec3(0, 0.5f, 0) - frame.eye;
  const float z = glm::dot(d, frame.forward);
  const float ex = (glm::dot(d, frame.right) / z / frame.scale_x + 1) * 0.5f * 161;
  const float ey = (1 - glm::dot(d, frame.up) / z / frame.scale_y) * 0.5f * 121;
  int half_max_count[2] = {0, 0};
  for (int model = 0; model < 2; ++model) {
    scene.render.model = model == 0 ? ShadingModel::phong : ShadingModel::blinn_phong;
    const TermImages img = render(scene);
    int bx = 0, by = 0;
    float best = -1;
    for (int y = 0; y < 121; ++y)
      for (int x = 0; x < 161; ++x)
        if (img.specular.at(x, y).x > best) best = img.specular.at(x, y).x, bx = x, by = y;
    EXPECT_NEAR(bx + 0.5f, ex, 1.0f) << "model " << model;
    EXPECT_NEAR(by + 0.5f, ey, 1.0f) << "model " << model;
    for (const glm::vec3& p : img.specular.pixels) half_max_count[model] += p.x > 0.5f * best;
  }
  // At equal exponent the half-vector lobe is wider (about a 4x smaller effective exponent).
  EXPECT_GT(half_max_count[1], 2 * half_max_count[0]);
}

TEST(Renderer, SameSeedGivesSameImageAndOtherSeedsDiffer) {
  Scene scene = head_on_sphere_scene();
  scene.render.spp = 4;
  const TermImages a = render(scene), b = render(scene);
  EXPECT_EQ(0, std::memcmp(a.total.pixels.data(), b.total.pixels.data(),
                           a.total.pixels.size() * sizeof(glm::vec3)));
  scene.render.seed = 7;
  const TermImages c = render(scene);
  EXPECT_NE(0, std::memcmp(a.total.pixels.data(), c.total.pixels.data(),
                           a.total.pixels.size() * sizeof(glm::vec3)));
}

}  // namespace
}  // namespace gloss

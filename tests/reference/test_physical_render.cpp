// The reference path with ReferenceOptions::physical: a material's physical reference shaded as
// docs/spec/physical-reference.md says, at a pixel worked out by hand; materials without one,
// and every render without the option, unchanged.
#include <cmath>

#include <gtest/gtest.h>

#include "reference/reference_renderer.h"
#include "support/image_compare.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

using test::expect_rgb;
using test::head_on_sphere_scene;

ReferenceOptions physical() {
  ReferenceOptions o;
  o.physical = true;
  return o;
}

// The head-on sphere's centre pixel: n = v = (0, 0, 1); the light at (0, 3, 5): d = 5,
// l = (0, 0.6, 0.8), n.l = 0.8, att = 1 / (1 + 0.1 5 + 0.01 25) = 1 / 1.75, Ld = 1.
// h = normalize(0, 0.6, 1.8): n.h = v.h = sqrt(0.9) = 0.9486833.
// Gold, roughness 0.5: a = 0.25, a^2 = 0.0625.
//   D: 0.9 (0.0625 - 1) + 1 = 0.15625; D = 0.0625 / (pi 0.15625^2) = 2.56 / pi = 0.8148733
//   Lambda(0.8): tan^2 = 0.36 / 0.64 = 0.5625; sqrt(1 + 0.0625 0.5625) = 1.0174263;
//   Lambda = 0.0087131; Lambda(1) = 0; G2 = 1 / 1.0087131 = 0.9913621
//   F: (1 - 0.9486833)^5 = 3.5587e-7, so F = F0 + (1 - F0) 3.5587e-7 = (1, 0.7820001, 0.3440002)
//   f = D G2 F / (4 0.8 1) = 0.2524480 F
//   radiance = pi f Ld n.l att = pi 0.2524480 F 0.8 / 1.75 = 0.3625553 F
//            = (0.3625553, 0.2835183, 0.1247191)
TEST(PhysicalRender, GoldCentrePixelByHand) {
  Scene scene = head_on_sphere_scene();
  PhysicalReference gold;
  gold.roughness = 0.5f;
  scene.materials[0].reference = gold;
  const TermImages img = render_reference<double>(scene, physical());
  expect_rgb(img.specular.at(50, 50), 0.3625553, 0.2835183, 0.1247191, 2e-6);
  expect_rgb(img.diffuse.at(50, 50), 0.0, 0.0, 0.0, 0.0);
  // Ambient and emission stay the material's ka (A_scene + La) and ke.
  expect_rgb(img.ambient.at(50, 50), 0.1 * 0.3, 0.2 * 0.3, 0.3 * 0.3, 1e-7);
  expect_rgb(img.emissive.at(50, 50), 0.01, 0.0, 0.0, 1e-7);
}

// A dielectric of base 0.5 at the same pixel: F = 0.04 + 0.96 3.5587e-7 = 0.0400003;
// specular = 0.3625553 0.0400003 = 0.0145023; diffuse = pi (1 - F) base / pi n.l att
// = 0.9599997 0.5 0.8 / 1.75 = 0.2194285.
TEST(PhysicalRender, DielectricCentrePixelByHand) {
  Scene scene = head_on_sphere_scene();
  PhysicalReference plastic;
  plastic.kind = ReferenceKind::dielectric;
  plastic.base = glm::vec3(0.5f);
  plastic.roughness = 0.5f;
  scene.materials[0].reference = plastic;
  const TermImages img = render_reference<double>(scene, physical());
  expect_rgb(img.specular.at(50, 50), 0.0145023, 0.0145023, 0.0145023, 2e-7);
  expect_rgb(img.diffuse.at(50, 50), 0.2194285, 0.2194285, 0.2194285, 2e-7);
}

// Without the option, or for a material without a reference, the image is the contract's, bit
// for bit.
TEST(PhysicalRender, OtherwiseUnchanged) {
  Scene scene = head_on_sphere_scene();
  const TermImages phong = render_reference<double>(scene);
  EXPECT_EQ(render_reference<double>(scene, physical()).total.pixels, phong.total.pixels);
  scene.materials[0].reference = PhysicalReference{};
  EXPECT_EQ(render_reference<double>(scene).total.pixels, phong.total.pixels);
  EXPECT_NE(render_reference<double>(scene, physical()).total.pixels, phong.total.pixels);
}

// Shadows apply to the reference as to Phong: with the light straight above the sphere, its
// shadow on the floor takes the reference's diffuse away from some floor pixels.
TEST(PhysicalRender, ShadowedPointsGetNoLight) {
  Scene scene = test::sphere_on_floor_scene();
  scene.render.spp = 1;
  scene.lights[0].position = {0.0f, 5.0f, 0.0f};
  for (Material& m : scene.materials) {
    PhysicalReference r;
    r.kind = ReferenceKind::dielectric;
    m.reference = r;
  }
  auto unlit = [](const TermImages& img) {
    int n = 0;
    for (const glm::vec3& d : img.diffuse.pixels) n += d.x > 0.0f ? 0 : 1;
    return n;
  };
  const int shadowed = unlit(render_reference<double>(scene, physical()));
  scene.render.shadows = false;
  const int open = unlit(render_reference<double>(scene, physical()));
  EXPECT_GT(shadowed, open + 20);
}

}  // namespace
}  // namespace gloss

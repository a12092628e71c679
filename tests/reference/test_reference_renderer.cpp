// The reference path (render_reference): equal to values computed by hand and by an independent
// long-double evaluation of docs/spec/shading.md, and the fast float renderer's agreement with it
// (spec: 1e-4 on interior pixels for alpha up to 1000; flipped pixels counted and reported).
#include "reference/reference_renderer.h"

#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "analysis/image/image_metrics.h"
#include "engine/renderer.h"
#include "io/scene/scene_loader.h"
#include "support/image_compare.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

using test::expect_rgb;
using test::head_on_sphere_scene;

// Centre pixel of the head-on sphere, by hand: p = n = v = (0,0,1); light (0,3,5): d = 5,
// l = (0,0.6,0.8), ndl = 0.8, att = 1/(1 + 0.1*5 + 0.01*25) = 1/1.75. Phong: R = (0,-0.6,0.8),
// c = 0.8, c^10 = 0.1073741824. Blinn: c = 1.8/sqrt(3.6) = sqrt(0.9), c^10 = 0.59049.
template <class T>
void check_head_on_centre(double tol) {
  Scene scene = head_on_sphere_scene();
  const TermImages img = render_reference<T>(scene);
  const double att = 1.0 / 1.75;
  expect_rgb(img.emissive.at(50, 50), 0.01, 0.0, 0.0, tol);
  expect_rgb(img.ambient.at(50, 50), 0.1 * 0.3, 0.2 * 0.3, 0.3 * 0.3, tol);
  expect_rgb(img.diffuse.at(50, 50), 0.5 * 0.8 * att, 0.4 * 0.8 * att, 0.3 * 0.8 * att, tol);
  const double s = 0.8 * 0.1073741824 * att;
  expect_rgb(img.specular.at(50, 50), s, s * 0.5, s * 0.25, tol);
  const double total_r = 0.01 + 0.03 + 0.4 * att + s;
  EXPECT_NEAR(img.total.at(50, 50).x, total_r, tol);
  expect_rgb(img.total.at(0, 0), 0, 0, 0, 0.0);  // a miss: black background
  scene.render.model = ShadingModel::blinn_phong;
  const double sb = 0.8 * 0.59049 * att;
  expect_rgb(render_reference<T>(scene).specular.at(50, 50), sb, sb * 0.5, sb * 0.25, tol);
}

TEST(ReferenceRenderer, DoubleHeadOnSphereCentreMatchesHandComputation) {
  check_head_on_centre<double>(1e-7);
}

TEST(ReferenceRenderer, FloatHeadOnSphereCentreMatchesHandComputation) {
  check_head_on_centre<float>(1e-5);
}

// The contract evaluated independently in long double, straight from docs/spec/shading.md, for one
// pixel centre of the head-on sphere (camera f = (0,0,-1), r = (1,0,0), u = (0,1,0) worked out by
// hand from eye (0,0,5), target 0, up y).
struct Ld3 {
  long double x, y, z;
};
Ld3 operator+(Ld3 a, Ld3 b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
Ld3 operator-(Ld3 a, Ld3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Ld3 operator*(long double s, Ld3 a) {
  return {s * a.x, s * a.y, s * a.z};
}
long double dot(Ld3 a, Ld3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
Ld3 unit(Ld3 a) {
  return (1.0L / std::sqrt(dot(a, a))) * a;
}

// Returns the red channel of diffuse and specular (Phong) at pixel (x, y) of the 101 x 101 image.
void head_on_by_long_double(int x, int y, long double& diffuse_r, long double& specular_r) {
  const long double pi = 3.141592653589793238462643383279502884L;
  const long double tan_half = std::tan(20.0L * pi / 180.0L);
  const long double sx = (2.0L * (x + 0.5L) / 101.0L - 1.0L) * tan_half;
  const long double sy = (1.0L - 2.0L * (y + 0.5L) / 101.0L) * tan_half;
  const Ld3 eye{0, 0, 5};
  const Ld3 d = unit(Ld3{sx, sy, -1.0L});
  const long double b = dot(eye, d);
  const long double t = -b - std::sqrt(b * b - (dot(eye, eye) - 1.0L));
  const Ld3 p = eye + t * d;
  const Ld3 n = p;  // unit sphere at the origin
  const Ld3 v = unit(eye - p);
  const Ld3 to_light = Ld3{0, 3, 5} - p;
  const long double dist = std::sqrt(dot(to_light, to_light));
  const Ld3 l = (1.0L / dist) * to_light;
  const long double ndl = dot(n, l);
  const long double att = 1.0L / (1.0L + 0.1L * dist + 0.01L * dist * dist);
  diffuse_r = 0.5L * ndl * att;
  const long double c = dot(2.0L * ndl * n - l, v);
  specular_r = c > 0 ? 0.8L * std::pow(c, 10.0L) * att : 0.0L;
}

TEST(ReferenceRenderer, DoubleMatchesIndependentLongDoubleEvaluationOffAxis) {
  const TermImages img = render_reference<double>(head_on_sphere_scene());
  for (const auto& [x, y] : {std::pair{60, 35}, std::pair{35, 62}, std::pair{50, 28}}) {
    long double diffuse = 0, specular = 0;
    head_on_by_long_double(x, y, diffuse, specular);
    ASSERT_GT(diffuse, 0.0L) << x << "," << y;  // on the sphere's lit side
    // The images are float: half an ulp of values below 1 is under 6e-8.
    EXPECT_NEAR(img.diffuse.at(x, y).x, static_cast<double>(diffuse), 1e-7) << x << "," << y;
    EXPECT_NEAR(img.specular.at(x, y).x, static_cast<double>(specular), 1e-7) << x << "," << y;
  }
}

// Shipped scenes at a small size, every material at the given shininess (0: as shipped): the
// fast float renderer against the double reference at the same samples.
struct Agreement {
  ImageMetrics interior, edges;
  double edge_share = 0;  // of all pixels
};

Agreement fast_against_reference(const std::string& name, float shininess) {
  Scene scene = load_scene(std::string(GLOSS_ASSETS_DIR) + "/scenes/" + name);
  scene.render.width = 200;
  scene.render.height = 150;
  scene.render.spp = 1;
  if (shininess > 0) {
    for (Material& m : scene.materials) m.shininess = shininess;
  }
  std::vector<std::uint8_t> edges;
  ReferenceOptions options;
  options.edges = &edges;
  const TermImages ref = render_reference<double>(scene, options);
  const TermImages fast = render(scene);
  Agreement a;
  a.interior = compare_images(fast.total, ref.total, edges, 0);
  a.edges = compare_images(fast.total, ref.total, edges, 1);
  a.edge_share = static_cast<double>(a.edges.pixels) / static_cast<double>(edges.size());
  return a;
}

class ShippedScene : public ::testing::TestWithParam<const char*> {};

TEST_P(ShippedScene, FastFloatAgreesWithDoubleOnInteriorPixelsUpToAlpha1000) {
  for (float alpha : {0.0f, 128.0f, 1000.0f}) {
    const Agreement a = fast_against_reference(GetParam(), alpha);
    // Reported, never hidden: how many pixels sit at a silhouette or shadow edge and how far
    // the float renderer is from the reference there.
    std::cout << "[ report   ] " << GetParam() << " alpha " << (alpha > 0 ? alpha : -1.0f)
              << ": interior " << a.interior.pixels << " px, max |diff| " << a.interior.max_abs
              << "; edges " << a.edges.pixels << " px (" << 100.0 * a.edge_share
              << " %), max |diff| " << a.edges.max_abs
              << ", off by > 1/255: " << a.edges.pct_pixels_off << " % of them\n";
    // Float primary rays (relative rounding near 1e-7) once failed this on presets.json: steep
    // highlights on small spheres seen from 30 units away (docs/accuracy.md).
    EXPECT_LE(a.interior.max_abs, 1e-4)
        << GetParam() << ", shininess " << (alpha > 0 ? std::to_string(alpha) : "as shipped");
    EXPECT_GT(a.interior.pixels, 0u);
    // Silhouettes and shadow boundaries are lines: a small share of a 200 x 150 image.
    EXPECT_LT(a.edge_share, 0.25) << GetParam();
  }
}

INSTANTIATE_TEST_SUITE_P(AllShipped, ShippedScene,
                         ::testing::Values("spheres.json", "cornell.json", "cornell-teapot.json",
                                           "teapot.json", "presets.json"),
                         [](const auto& info) {
                           std::string n = info.param;
                           n = n.substr(0, n.find('.'));
                           for (char& c : n) c = c == '-' ? '_' : c;
                           return n;
                         });

}  // namespace
}  // namespace gloss

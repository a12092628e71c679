#include "reference/lobe_sum.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "shading/environment.h"

namespace gloss {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

glm::dvec3 lobe_mean(const Image& map, const quadrature::Lobe& lobe, const glm::dvec3& mirror) {
  // A virtual grid s times finer than the map's texels, walked only within the lobe's reach.
  const double a = lobe.alpha;
  double reach = std::acos(std::pow(1e-6, 1.0 / (a + 1.0)));
  if (lobe.blinn) reach = std::min(kPi, 2.0 * reach);
  const double part = 0.049 / std::sqrt(a + 1.0);
  const int s = std::clamp(static_cast<int>(std::ceil((kPi / map.height) / part)), 1, 4096);
  const long long w = static_cast<long long>(map.width) * s,
                  h = static_cast<long long>(map.height) * s;
  // Parts near the horizon are cut 4 x 4 finer again.
  const double edge = 2.0 * kPi / std::min<long long>(w, 2 * h);
  const double theta_m = std::acos(std::clamp(mirror.y, -1.0, 1.0));
  const double phi_m = std::atan2(mirror.x, -mirror.z);
  const long long row0 =
      std::max(0LL, static_cast<long long>(std::floor((theta_m - reach) / kPi * h)) - 1);
  const long long row1 =
      std::min(h - 1, static_cast<long long>(std::floor((theta_m + reach) / kPi * h)) + 1);
  glm::dvec3 top(0.0);
  double bottom = 0.0;
  auto add = [&](double u0, double du, double t0, double dt) {
    const double omega = (std::cos(kPi * t0) - std::cos(kPi * (t0 + dt))) * 2.0 * kPi * du;
    const double u = u0 + 0.5 * du, t = t0 + 0.5 * dt;
    const double f = lobe.at(map_direction<double>(u, t));
    if (f == 0.0) return;
    top += map_bilinear<double>(map, u, t) * (f * omega);
    bottom += f * omega;
  };
  for (long long j = row0; j <= row1; ++j) {
    const double theta = kPi * (j + 0.5) / h;
    // The columns within reach of the axis (a whole row near a pole).
    long long half = w / 2 + 1;
    const double sm = std::sin(theta_m) * std::sin(theta);
    if (sm > 1e-12) {
      const double x = (std::cos(reach) - std::cos(theta_m) * std::cos(theta)) / sm;
      if (x > 1.0 && std::abs(theta - theta_m) > 2.0 * kPi / h) continue;
      if (x > -1.0) {
        half = static_cast<long long>(
                   std::ceil(std::acos(std::clamp(x, -1.0, 1.0)) / (2.0 * kPi) * w)) +
               2;
      }
    }
    const long long centre = static_cast<long long>(std::floor((phi_m / (2.0 * kPi) + 0.5) * w));
    const long long count = std::min(w, 2 * half + 1);
    const long long first = count == w ? 0 : centre - half;
    const double dt = 1.0 / double(h), t0 = double(j) / h, du = 1.0 / double(w);
    for (long long k = 0; k < count; ++k) {
      const long long i = ((first + k) % w + w) % w;
      const double u0 = double(i) / w;
      const glm::dvec3 c = map_direction<double>(u0 + 0.5 * du, t0 + 0.5 * dt);
      if (std::abs(glm::dot(lobe.n, c)) >= edge) {
        add(u0, du, t0, dt);
        continue;
      }
      for (int b = 0; b < 4; ++b) {
        for (int q = 0; q < 4; ++q) add(u0 + q * du / 4.0, du / 4.0, t0 + b * dt / 4.0, dt / 4.0);
      }
    }
  }
  return bottom > 0.0 ? top / bottom : glm::dvec3(0.0);
}

}  // namespace gloss

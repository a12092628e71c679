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
  const int w = map.width, h = map.height;
  // Where cos^(alpha + 1) of the angle from the lobe's axis falls to 1e-6 (its weight beyond is
  // that share of the whole); Blinn-Phong's half vector turns w twice as far.
  const double a = lobe.alpha;
  double reach = std::acos(std::pow(1e-6, 1.0 / (a + 1.0)));
  if (lobe.blinn) reach = std::min(kPi, 2.0 * reach);
  const double part = 0.049 / std::sqrt(a + 1.0);
  const int s = std::clamp(static_cast<int>(std::ceil((kPi / h) / part)), 1, 512);
  const double theta_m = std::acos(std::clamp(mirror.y, -1.0, 1.0));
  const double phi_m = std::atan2(mirror.x, -mirror.z);
  const int row0 = std::max(0, static_cast<int>(std::floor((theta_m - reach) / kPi * h)) - 1);
  const int row1 = std::min(h - 1, static_cast<int>(std::floor((theta_m + reach) / kPi * h)) + 1);
  glm::dvec3 top(0.0);
  double bottom = 0.0;
  for (int j = row0; j <= row1; ++j) {
    const double theta = kPi * (j + 0.5) / h;
    // The columns within reach of the axis (a whole row near a pole).
    int half = w / 2 + 1;
    const double sm = std::sin(theta_m) * std::sin(theta);
    if (sm > 1e-9) {
      const double x = (std::cos(reach) - std::cos(theta_m) * std::cos(theta)) / sm;
      if (x > 1.0 + 1e-9 && std::abs(theta - theta_m) > kPi / h) continue;
      if (x > -1.0) half = static_cast<int>(std::ceil(std::acos(std::clamp(x, -1.0, 1.0)) / (2.0 * kPi) * w)) + 2;
    }
    const int centre = static_cast<int>(std::floor((phi_m / (2.0 * kPi) + 0.5) * w));
    const int first = half * 2 + 1 >= w ? 0 : centre - half;
    const int count = std::min(w, 2 * half + 1);
    for (int k = 0; k < count; ++k) {
      const int i = ((first + k) % w + w) % w;
      // Parts of the texel: s x s, or 4 s x 4 s where the horizon may cross it.
      const glm::dvec3 c = map_direction<double>((i + 0.5) / w, (j + 0.5) / h);
      const bool edge = std::abs(glm::dot(lobe.n, c)) < 2.0 * kPi / std::min(w, 2 * h);
      const int parts = edge ? 4 * s : s;
      const double du = 1.0 / (double(w) * parts), dt = 1.0 / (double(h) * parts);
      for (int b = 0; b < parts; ++b) {
        const double t0 = double(j) / h + b * dt;
        const double omega = (std::cos(kPi * t0) - std::cos(kPi * (t0 + dt))) * 2.0 * kPi * du;
        const double t = t0 + 0.5 * dt;
        for (int q = 0; q < parts; ++q) {
          const double u = double(i) / w + (q + 0.5) * du;
          const double f = lobe.at(map_direction<double>(u, t));
          if (f == 0.0) continue;
          top += map_bilinear<double>(map, u, t) * (f * omega);
          bottom += f * omega;
        }
      }
    }
  }
  return bottom > 0.0 ? top / bottom : glm::dvec3(0.0);
}

}  // namespace gloss

#include "physical/lobe_samples.h"

#include <algorithm>
#include <cmath>

#include "physical/microfacet.h"
#include "shading/shading.h"

namespace gloss {

namespace {

constexpr double kHalfPi = kPi / 2.0;

}  // namespace

std::vector<AngleCell> half_angle_cells(double width, int per_decade, int even) {
  std::vector<double> bounds{0.0, kHalfPi};
  const double start = 1e-3 * width;
  for (int k = 0;; ++k) {
    const double b = start * std::pow(10.0, double(k) / std::max(per_decade, 1));
    if (!(b < kHalfPi)) break;
    bounds.push_back(b);
  }
  for (int j = 1; j < even; ++j) bounds.push_back(kHalfPi * j / even);
  std::sort(bounds.begin(), bounds.end());
  std::vector<AngleCell> cells;
  for (std::size_t i = 0; i + 1 < bounds.size(); ++i) {
    const double lo = bounds[i], hi = bounds[i + 1];
    if (!(hi > lo * (1.0 + 1e-9))) continue;  // a boundary given twice
    cells.push_back({lo > 0.0 ? std::sqrt(lo * hi) : 0.5 * hi, lo, hi});
  }
  return cells;
}

LobeSamples make_lobe_samples(const LobeGrid& grid) {
  LobeSamples out;
  out.grid = grid;
  const std::vector<AngleCell> half = half_angle_cells(grid.width, grid.per_decade, grid.even);
  const double d_theta = kHalfPi / grid.theta_d;
  const double d_phi = kPi / grid.phi_d;
  const glm::dvec3 n(0.0, 0.0, 1.0);
  const double min_cos =
      grid.max_angle_deg >= 90.0 ? 0.0 : std::cos(grid.max_angle_deg * kPi / 180.0);
  for (const AngleCell& h_cell : half) {
    const double th = h_cell.node;
    // integral of sin(theta_h) over the cell
    const double w_h = band_measure(h_cell.lo, h_cell.hi);
    const double ch = std::cos(th), sh = std::sin(th);
    for (int j = 0; j < grid.theta_d; ++j) {
      const double lo = j * d_theta, hi = lo + d_theta, td = lo + 0.5 * d_theta;
      // integral of cos(theta_d) sin(theta_d) over the cell
      const double w_d = 0.5 * (std::sin(hi) * std::sin(hi) - std::sin(lo) * std::sin(lo));
      const double cd = std::cos(td), sd = std::sin(td);
      for (int k = 0; k < grid.phi_d; ++k) {
        const double pd = (k + 0.5) * d_phi;
        // d in the half vector's frame, turned by theta_h about y (phi_h = 0).
        const glm::dvec3 d(sd * std::cos(pd), sd * std::sin(pd), cd);
        const glm::dvec3 l(d.x * ch + d.z * sh, d.y, -d.x * sh + d.z * ch);
        const glm::dvec3 h(sh, 0.0, ch);
        const glm::dvec3 v = 2.0 * glm::dot(l, h) * h - l;
        if (!(l.z > min_cos && v.z > min_cos)) continue;
        LobePair p;
        p.l = l;
        p.v = glm::normalize(v);
        // 4 (Jacobian) x 2 pi (phi_h) x 2 (phi_d mirrored) x the cells' measures
        p.weight = 4.0 * 2.0 * kPi * 2.0 * w_h * w_d * d_phi;
        p.angles = pair_cosines(n, p.l, p.v);
        p.angles.cos_h = ch;  // exact, rather than recomputed from l + v
        p.angles.sin_h = sh;
        const LightFactors<double> f = light_factors<double>(glm::dvec3(0.0), n, p.v, p.l,
                                                             glm::dvec3(1.0, 0.0, 0.0), true, 1.0);
        p.cos_phong = f.cos_phong;
        p.cos_blinn = f.cos_blinn;
        if (!p.angles.valid) continue;
        out.total_weight += p.weight;
        out.pairs.push_back(p);
      }
    }
  }
  return out;
}

double lobe_width_for_ggx(double a) {
  return std::clamp(a, 1e-4, 1.0);
}

double lobe_width_for_exponent(double blinn_alpha) {
  return std::clamp(std::sqrt(2.0 / (std::max(blinn_alpha, 0.0) + 2.0)), 1e-4, 1.0);
}

}  // namespace gloss

#include "physical/brdf_checks.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "physical/microfacet.h"

namespace gloss {

namespace {

// The albedo integral, with an optional cone about the mirror direction: sum over half vectors
// h of f(l, v) (n.l) 4 (v.h) d(omega_h), l = reflect(v, h), where n.l > 0.
glm::dvec3 albedo_in(const BrdfFunction& f, double cos_v, double width, int per_decade, int phi_h,
                     double cone_cos) {
  const double sv = std::sqrt(std::max(0.0, 1.0 - cos_v * cos_v));
  const glm::dvec3 v(sv, 0.0, cos_v), n(0.0, 0.0, 1.0);
  const glm::dvec3 mirror(-sv, 0.0, cos_v);
  glm::dvec3 sum(0.0);
  const double d_phi = 2.0 * kPi / phi_h;
  for (const AngleCell& cell : half_angle_cells(width, per_decade, 32)) {
    const double th = cell.node;
    const double measure = band_measure(cell.lo, cell.hi) * d_phi;
    for (int k = 0; k < phi_h; ++k) {
      const double ph = (k + 0.5) * d_phi;
      const glm::dvec3 h(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
      const double vdh = glm::dot(v, h);
      if (vdh <= 0.0) continue;
      const glm::dvec3 l = 2.0 * vdh * h - v;
      const double ndl = glm::dot(n, l);
      if (ndl <= 0.0) continue;
      if (glm::dot(l, mirror) < cone_cos) continue;
      sum += f(l, v) * (ndl * 4.0 * vdh * measure);
    }
  }
  return sum;
}

}  // namespace

BrdfFunction brdf_function(const ReferenceBrdf& brdf) {
  return [brdf](const glm::dvec3& l, const glm::dvec3& v) {
    return evaluate_brdf(brdf, glm::dvec3(0.0, 0.0, 1.0), l, v).total();
  };
}

double reciprocity_error(const BrdfFunction& f, const LobeSamples& samples) {
  double worst = 0.0;
  for (const LobePair& p : samples.pairs) {
    const glm::dvec3 a = f(p.l, p.v), b = f(p.v, p.l);
    for (int c = 0; c < 3; ++c) {
      const double m = std::max(std::fabs(a[c]), std::fabs(b[c]));
      if (m > 0.0) worst = std::max(worst, std::fabs(a[c] - b[c]) / m);
    }
  }
  return worst;
}

glm::dvec3 directional_albedo(const BrdfFunction& f, double cos_v, double width, int per_decade,
                              int phi_h) {
  return albedo_in(f, cos_v, width, per_decade, phi_h, -2.0);
}

double mirror_share(const BrdfFunction& f, double cos_v, double width, double cone_deg,
                    int per_decade, int phi_h) {
  const glm::dvec3 all = albedo_in(f, cos_v, width, per_decade, phi_h, -2.0);
  const glm::dvec3 cone =
      albedo_in(f, cos_v, width, per_decade, phi_h, std::cos(cone_deg * kPi / 180.0));
  const double total = all.x + all.y + all.z;
  return total > 0.0 ? (cone.x + cone.y + cone.z) / total : 0.0;
}

}  // namespace gloss

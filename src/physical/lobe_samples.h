#pragma once
// Pairs of light and view directions over the hemisphere, with quadrature weights of the measure
// d(omega_l) d(omega_v): what the fit (physical/phong_fit.h) and the error metrics
// (physical/lobe_metrics.h) integrate over. Frame: the normal is +z.
//
// The pairs are laid out in Rusinkiewicz's half/difference angles (theta_h, theta_d, phi_d), as
// measured BRDFs are (Ngan et al. 2005 fit in them): d(omega_l) d(omega_v) = 4 cos(theta_d)
// d(omega_h) d(omega_d), and an isotropic lobe does not depend on phi_h, which integrates to
// 2 pi. Half-vector angles are spaced evenly in log(theta_h) about the lobe's width, so a narrow
// highlight is resolved as well as a broad one; difference angles are even. Every pair has both
// directions above the surface (and within max_angle_deg of the normal); over the whole
// hemispheres the weights add up to (2 pi)^2 (to the quadrature's error,
// tests/physical/test_lobe_samples.cpp).
#include <vector>

#include <glm/vec3.hpp>

#include "physical/reference_brdf.h"

namespace gloss {

struct LobeGrid {
  // The lobe's angular scale, radians: GGX's a, or about sqrt(2 / (alpha + 2)) for a
  // Blinn-Phong exponent alpha. Half-vector angles are spaced evenly in log(theta_h) from a
  // thousandth of it up to 90 degrees, so a lobe of any width gets as many cells per decade.
  double width = 0.3;
  int per_decade = 20;  // half-vector cells per decade of theta_h
  int even = 16;        // ... and boundaries every 90 / even degrees, for the broad parts
  int theta_d = 20;     // difference angles, even over 0..90 degrees
  int phi_d = 20;       // difference azimuths, even over 0..180 (isotropy mirrors the other half)
  // Pairs whose light or view is further than this from the normal are left out, degrees. Ngan
  // et al. left out 80..90 (measurements there are unreliable); here it keeps a fit from being
  // ruled by the rims of objects, where the reference's highlight grows as 1 / (n.v) and no
  // Phong lobe follows (docs/phong-vs-reference.md shows both).
  double max_angle_deg = 80.0;
};

// A cell [lo, hi] of half-vector angles (radians) and the angle it is evaluated at: the
// geometric mean of its ends (the midpoint in log(theta_h); hi / 2 for the cell at 0).
struct AngleCell {
  double node = 0.0, lo = 0.0, hi = 0.0;
};

// The half-vector cells of a grid, covering [0, pi/2]: for the pairs, and for the integrals over
// half vectors of physical/brdf_checks.h.
std::vector<AngleCell> half_angle_cells(double width, int per_decade, int even);

// One pair. The cosines are computed once, with the shading contract's own function for the
// Phong and Blinn-Phong ones (shading.h light_factors), so a fit sees what the renderer computes.
struct LobePair {
  glm::dvec3 l{0.0, 0.0, 1.0}, v{0.0, 0.0, 1.0};  // unit, towards the light and the viewer
  double weight = 0.0;     // this pair's share of the measure d(omega_l) d(omega_v), sr^2
  PairCosines angles;      // n.l, n.v, the half vector's cosine and sine, v.h
  double cos_phong = 0.0;  // R . V of the contract
  double cos_blinn = 0.0;  // N . H of the contract
};

struct LobeSamples {
  LobeGrid grid;
  std::vector<LobePair> pairs;
  double total_weight = 0.0;  // sum of the weights, about (2 pi)^2
};

LobeSamples make_lobe_samples(const LobeGrid& grid);

// The grid width for a GGX width a, and for a Phong or Blinn-Phong exponent (a Phong lobe of
// exponent alpha is about as wide as a Blinn-Phong lobe of 4 alpha; document.h's rule).
double lobe_width_for_ggx(double a);
double lobe_width_for_exponent(double blinn_alpha);

}  // namespace gloss

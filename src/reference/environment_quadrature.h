#pragma once
// The environment light's unshadowed integrals of docs/spec/shading.md in double, with a bound
// on their error: the reference path's (and the pixel inspector's) exact value.
//
// The map's domain (u, t) is cut into cells: texels, blocks of texels (a tree of moments made
// once per map: per cell the integrals of L and of L w over the sphere), and below a texel its
// four bilinear quarters and their halves (moments by 3 x 3 Gauss-Legendre on the bilinear L,
// whose own error is below 1e-12 of a cell's integral). On a cell whose directions lie within
// angle rho of its centre c, where the lobe f is smooth (no horizon or lobe edge crosses it),
//   integral of L f = f(c) M0 + grad f(c) . (M1 - c M0) + R,  |R| <= (1/2) max|Hess f| rho^2 M0
// (Taylor's theorem on the sphere's chords, rho an angle >= the chord); where an edge crosses
// it, the estimate is (1/2) f_max M0 with the bound (1/2) f_max M0. Cells are split, the one of
// the largest bound first, until the bounds sum to at most `tolerance` times the estimate (or
// 500,000 cells are spent): `bound` is that sum. On cells of a texel or less that an edge
// crosses, and for the Blinn-Phong lobe below a texel, the estimate is 3 x 3 Gauss-Legendre of L
// f over the cell's pieces and their quarters, its error their difference: there `bound` is an
// estimate, elsewhere a bound (up to floating-point rounding and the cone radii, 1.01 times the
// largest angle from c to 16 points of the cell's boundary). Cost grows with alpha and falls
// with tolerance^(2/3): tens of milliseconds per pixel at 1e-3 for the presets' exponents.
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/environment.h"
#include "scene/render_settings.h"

namespace gloss {

struct QuadratureResult {
  glm::dvec3 value{0.0};  // the integral's estimate
  glm::dvec3 bound{0.0};  // |value - exact| <= bound, per channel
  long long cells = 0;    // cells evaluated
};

class EnvironmentQuadrature {
 public:
  // Builds the moment tree of map (about 100 bytes per texel).
  explicit EnvironmentQuadrature(std::shared_ptr<const EnvironmentMap> map);
  ~EnvironmentQuadrature();
  EnvironmentQuadrature(const EnvironmentQuadrature&) = delete;
  EnvironmentQuadrature& operator=(const EnvironmentQuadrature&) = delete;

  // For unit map-frame vectors (shading/environment.h to_map_frame), at intensity 1:
  // diffuse: (1 / pi) integral of L max(0, n.w);
  // specular: integral of L lobe over integral of lobe, the lobe of shading/environment.h
  // specular_lobe (the contract's, with its horizon); the bound covers both integrals' errors.
  QuadratureResult diffuse(const glm::dvec3& n, double tolerance = 1e-3) const;
  QuadratureResult specular(ShadingModel model, const glm::dvec3& n, const glm::dvec3& v,
                            const glm::dvec3& r, double alpha, double tolerance = 1e-3) const;

  // The specular term by reference/lobe_sum.h's texel sum (no bound: its rule's error is about
  // 1e-4 of the value; much cheaper above alpha ~ 16). The reference images use it.
  glm::dvec3 specular_sum(ShadingModel model, const glm::dvec3& n, const glm::dvec3& v,
                          const glm::dvec3& r, double alpha) const;

  std::uint64_t bytes() const;

 private:
  struct Tree;
  std::unique_ptr<Tree> m_tree;
};

// The quadrature of map, shared: made the first time and kept for the last few maps.
std::shared_ptr<const EnvironmentQuadrature> environment_quadrature(
    const std::shared_ptr<const EnvironmentMap>& map);

}  // namespace gloss

#pragma once
// The cells of environment_quadrature.h (reference's own): a cell's moments (per channel the
// integrals of L, L w and L w w^T over it), its cone of directions, and what a lobe's integral
// over it is with a bound or an estimate of its error.
#include <glm/vec3.hpp>

#include "base/image.h"
#include "scene/render_settings.h"

namespace gloss::quadrature {

// Per channel: integrals of L, L (w - c) and L (w - c)(w - c)^T (xx, xy, xz, yy, yz, zz) over a
// cell, about a point c (the origin for the tree's blocks, the cell's centre direction where
// made on the fly: about the centre, a tiny cell's moments keep their precision).
struct Moments {
  glm::dvec3 m0{0.0};
  glm::dvec3 m1[3] = {};
  double m2[3][6] = {};
  Moments& operator+=(const Moments& o);
  // The same moments about c instead of the origin (for moments about the origin).
  Moments about(const glm::dvec3& c) const;
};

// Over the (u, t) rectangle [u0, u1] x [t0, t1] inside one bilinear piece of the map's L:
// 3 x 3 Gauss-Legendre (the bilinear L times w w^T and the Jacobian: smooth, its error below
// 1e-12 of the cell's integral for cells of a texel or less).
// unit: L = 1. About c.
Moments rectangle_moments(const Image& map, bool unit, double u0, double u1, double t0, double t1,
                          const glm::dvec3& c);
// For L = 1 over any rectangle, in closed form, about the origin.
Moments unit_moments(double u0, double u1, double t0, double t1);

// A centre direction and a radius no smaller than the angle to any direction of the rectangle:
// 1.01 times the largest angle to 16 points of its boundary (pi for cells wider than 90
// degrees).
void cone_of(double u0, double u1, double t0, double t1, glm::dvec3& centre, double& radius);

// A lobe of shading/environment.h (specular_lobe: Phong about r or Blinn-Phong, with the horizon
// of n; the diffuse clamped cosine is Phong's with r = n and alpha = 1).
struct Lobe {
  bool blinn = false;
  glm::dvec3 axis{0.0}, n{0.0}, v{0.0};
  double alpha = 0.0;

  double at(const glm::dvec3& w) const;

  // What it is on the sphere's cell with these moments (about the cone's centre) and cone:
  // value and error (a bound), smooth when no edge (horizon, lobe's end) crosses the cell.
  // zero: the lobe is 0 there.
  struct Part {
    glm::dvec3 value{0.0}, error{0.0};
    bool zero = false, smooth = false, bounded = false;
  };
  Part on(const Moments& m, const glm::dvec3& centre, double radius) const;
};

// 3 x 3 Gauss-Legendre of L times the lobe over a rectangle inside one bilinear piece of L
// (unit: L = 1), for cells an edge crosses.
glm::dvec3 sampled_integral(const Image& map, bool unit, const Lobe& lobe, double u0, double u1,
                            double t0, double t1);

}  // namespace gloss::quadrature

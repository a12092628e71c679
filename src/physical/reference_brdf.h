#pragma once
// The physical reference material as a BRDF (docs/spec/physical-reference.md), in double:
//
//   f_spec = D(h) G2(l, v) F(v.h) / (4 (n.l) (n.v))         GGX, height-correlated Smith, Schlick
//   conductor:  f = f_spec                                   F0 from the measured table
//   dielectric: f = f_spec (F0 = 0.04) + (1 - F(v.h)) base / pi
//   f = 0 where n.l <= 0 or n.v <= 0
//
// Under a light of the shading contract the reference adds pi f Ld ndl att vis, so a white
// Lambertian base of 1 gives what kd = 1 gives.
#include <glm/vec3.hpp>

#include "scene/physical_reference.h"

namespace gloss {

struct ReferenceBrdf {
  glm::dvec3 f0{0.04};   // Schlick's normal-incidence reflectance, per channel
  glm::dvec3 base{0.0};  // Lambertian albedo under the Fresnel coat; 0 for conductors
  double a = 0.09;       // GGX width, roughness^2, > 0
  bool dielectric = false;
};

// The BRDF a material's reference describes.
ReferenceBrdf make_reference_brdf(const PhysicalReference& reference);
// A conductor of any F0 (F0 = 1: the mirror-limit check).
ReferenceBrdf conductor_brdf(const glm::dvec3& f0, double roughness);

// The angles one pair of directions gives every term: n.l, n.v, the half vector's cosine and
// sine to n, and v.h. valid is false where n.l <= 0 or n.v <= 0 (f = 0 there).
struct PairCosines {
  double ndl = 0.0, ndv = 0.0, cos_h = 1.0, sin_h = 0.0, vdh = 1.0;
  bool valid = false;
};

// From unit vectors: n the normal, l towards the light, v towards the viewer.
PairCosines pair_cosines(const glm::dvec3& n, const glm::dvec3& l, const glm::dvec3& v);

// f split by term, 1/sr, linear RGB: the specular microfacet lobe and the dielectric's diffuse.
struct BrdfValue {
  glm::dvec3 diffuse{0.0};
  glm::dvec3 specular{0.0};
  glm::dvec3 total() const { return diffuse + specular; }
};

BrdfValue evaluate_brdf(const ReferenceBrdf& brdf, const PairCosines& c);
BrdfValue evaluate_brdf(const ReferenceBrdf& brdf, const glm::dvec3& n, const glm::dvec3& l,
                        const glm::dvec3& v);

}  // namespace gloss

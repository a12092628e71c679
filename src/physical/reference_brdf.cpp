#include "physical/reference_brdf.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "physical/measured_metals.h"
#include "physical/microfacet.h"

namespace gloss {

ReferenceBrdf make_reference_brdf(const PhysicalReference& reference) {
  ReferenceBrdf brdf;
  const double r = reference.roughness;
  brdf.a = r * r;
  brdf.f0 = reference_f0(reference.kind);
  brdf.dielectric = !is_metal(reference.kind);
  brdf.base = brdf.dielectric ? glm::dvec3(reference.base) : glm::dvec3(0.0);
  return brdf;
}

ReferenceBrdf conductor_brdf(const glm::dvec3& f0, double roughness) {
  ReferenceBrdf brdf;
  brdf.f0 = f0;
  brdf.a = roughness * roughness;
  return brdf;
}

PairCosines pair_cosines(const glm::dvec3& n, const glm::dvec3& l, const glm::dvec3& v) {
  PairCosines c;
  c.ndl = glm::dot(n, l);
  c.ndv = glm::dot(n, v);
  const glm::dvec3 h = l + v;
  const double h_len = glm::length(h);
  c.valid = c.ndl > 0.0 && c.ndv > 0.0 && h_len > 0.0;
  if (!c.valid) return c;
  c.cos_h = glm::dot(n, h) / h_len;
  c.sin_h = glm::length(glm::cross(n, h)) / h_len;
  c.vdh = glm::dot(v, h) / h_len;
  return c;
}

BrdfValue evaluate_brdf(const ReferenceBrdf& brdf, const PairCosines& c) {
  BrdfValue f;
  if (!c.valid) return f;
  const double d = ggx_distribution(c.cos_h, c.sin_h, brdf.a);
  const double g2 = smith_g2(c.ndl, c.ndv, brdf.a);
  const glm::dvec3 fresnel = schlick_fresnel(brdf.f0, c.vdh);
  f.specular = fresnel * (d * g2 / (4.0 * c.ndl * c.ndv));
  if (brdf.dielectric) f.diffuse = (glm::dvec3(1.0) - fresnel) * brdf.base / kPi;
  return f;
}

BrdfValue evaluate_brdf(const ReferenceBrdf& brdf, const glm::dvec3& n, const glm::dvec3& l,
                        const glm::dvec3& v) {
  return evaluate_brdf(brdf, pair_cosines(n, l, v));
}

}  // namespace gloss

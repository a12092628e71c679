#pragma once
// The checks that prove a BRDF right (docs/spec/physical-reference.md, "Checks"), written over
// any BRDF given as a function, so tests can run them on the reference and on variants with a
// planted error and see them fail.
#include <functional>

#include <glm/vec3.hpp>

#include "physical/lobe_samples.h"
#include "physical/reference_brdf.h"

namespace gloss {

// f(l, v) for unit l and v in the frame whose normal is +z, 1/sr, linear RGB.
using BrdfFunction = std::function<glm::dvec3(const glm::dvec3& l, const glm::dvec3& v)>;

BrdfFunction brdf_function(const ReferenceBrdf& brdf);

// Reciprocity: the largest |f(l, v) - f(v, l)| / max(|f(l, v)|, |f(v, l)|) over the pairs
// (0 for a reciprocal BRDF, to rounding).
double reciprocity_error(const BrdfFunction& f, const LobeSamples& samples);

// The directional albedo, integral of f(l, v) cos(theta_l) d(omega_l) over the hemisphere for
// the view at cos_v: what a white furnace (a uniform environment of radiance 1) reflects
// towards v. Integrated over half vectors (d(omega_l) = 4 (v.h) d(omega_h)) on the half-vector
// cells of physical/lobe_samples.h about width (GGX's a) at per_decade cells per decade, times
// phi_h azimuths, so narrow lobes are resolved.
glm::dvec3 directional_albedo(const BrdfFunction& f, double cos_v, double width,
                              int per_decade = 40, int phi_h = 128);

// The share of the directional albedo that arrives from within cone_deg of the mirror direction
// of v (near 1 for a mirror).
double mirror_share(const BrdfFunction& f, double cos_v, double width, double cone_deg,
                    int per_decade = 40, int phi_h = 128);

}  // namespace gloss

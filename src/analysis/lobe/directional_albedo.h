#pragma once
// Directional albedo of a material's point-light terms (the editor's lobe view, "albedo"): the
// share of a unit directional light's irradiance that the contract's diffuse and specular terms
// send into the hemisphere above the surface, against the light's incidence angle.
//
// Units: the contract's terms are radiance L(v) under a light of unit colours (Ld = Ls = 1,
// attenuation 1, visible): L(v) = kd ndl + ks c^alpha [x normalisation] (shading/shading.h). A
// Lambertian BRDF kd / pi gives kd ndl under an irradiance of pi, so that is the unit light's
// irradiance at normal incidence, pi cos(theta_i) at incidence theta_i, and
//     albedo(theta_i) = 1 / (pi cos theta_i)  x  integral over the hemisphere of L(v) (n . v) dv.
// A Lambertian kd then gives kd at every angle, and Phong's specular at normal incidence gives
// ks x 2 / (alpha + 2) (ks / pi with the energy normalisation (alpha + 2) / 2pi); classic Phong is
// not energy conserving, so its specular albedo grows past 1 towards grazing incidence.
//
// The integral is evaluated with the contract's own functions (light_factors, specular_power,
// energy_normalization) over directions v parameterised about the mirror direction R by
// t = cos(angle to R) and the azimuth phi; 1 - t is substituted (1 - t = -ln(1 - u (1 - e^-k)) / k,
// k the lobe's exponent, so that c^k ~ e^(-k (1 - t)) is flat in u) so that a narrow lobe's
// samples gather at its peak, the visible arc of each ring is
// found exactly (the horizon is an end of the phi integral, not a kink in it), and both
// integrals are adaptive Gauss-Kronrod (Boost.Math, header only), each with its error estimate:
// `error` is their sum, the result's estimated absolute error.
#include <atomic>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/material.h"
#include "scene/render_settings.h"

namespace gloss {

// The hemisphere integrals of one term for a unit light at incidence_deg (0: along the normal,
// 90: grazing), divided by pi cos(theta_i) (the unit light's irradiance).
struct AlbedoTerms {
  double incidence_deg = 0.0;
  double diffuse = 0.0;        // the diffuse weight's share: kd times this is the diffuse albedo
  double phong = 0.0;          // the Phong specular's share (ks times this), normalised as asked
  double blinn = 0.0;          // the Blinn-Phong specular's share (ks times this)
  double diffuse_error = 0.0;  // each share's estimated absolute error
  double phong_error = 0.0;
  double blinn_error = 0.0;
};

// The models' exponents and normalisation (also the lobe view's 3D plot's, lobe_weights).
struct AlbedoParams {
  double phong_alpha = 32.0, blinn_alpha = 32.0;  // exponents, >= 0
  bool energy_normalize = false;
  double tolerance = 1e-7;  // relative error asked of each integral
  bool operator==(const AlbedoParams& o) const {
    return phong_alpha == o.phong_alpha && blinn_alpha == o.blinn_alpha &&
           energy_normalize == o.energy_normalize && tolerance == o.tolerance;
  }
};

// The contract's weights towards one outgoing direction v for a unit light from direction l
// (both unit, the normal +y): the diffuse weight (ndl) and each model's specular weight x c^alpha
// (x normalisation), from light_factors, specular_power and energy_normalization. A material's
// radiance is kd x diffuse + ks x phong (or blinn).
struct LobeWeights {
  double diffuse = 0.0, phong = 0.0, blinn = 0.0;
};
LobeWeights lobe_weights(const AlbedoParams& params, const glm::dvec3& l, const glm::dvec3& v);

// The shares at one incidence angle, 0 <= incidence_deg < 90.
AlbedoTerms albedo_terms(const AlbedoParams& params, double incidence_deg);

// A material's albedo, linear RGB: kd x diffuse + ks x specular share of model.
glm::dvec3 directional_albedo(const Material& material, const AlbedoTerms& terms,
                              ShadingModel model);

// The curve: count incidence angles evenly spaced over [0, max_deg]; empty when cancel turns
// true (checked between angles).
std::vector<AlbedoTerms> albedo_curve(const AlbedoParams& params, int count, double max_deg,
                                      const std::atomic<bool>* cancel = nullptr);

}  // namespace gloss

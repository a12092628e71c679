#pragma once
// The lobe of a material in the plane of incidence (the editor's lobe view, docs/editor.md):
// the radiance a surface point reflects towards each outgoing angle under one point light of
// unit colours (La = 0, Ld = Ls = 1, attenuation 1, visible), evaluated in double with the
// contract's own functions (shading/shading.h: light_factors, specular_power,
// energy_normalization), so the curves are what the renderer computes for those directions; and,
// for a material with a physical reference, what the reference path renders there.
//
// Frame: the surface normal is +y, the plane of incidence is x-y. The light comes from the
// left (-x) at elevation e above the surface, l = (-cos e, sin e, 0). An outgoing angle theta is
// measured from the normal, positive towards the mirror side: v = (sin theta, cos theta, 0). The
// mirror direction is theta = 90 - e; theta = -(90 - e) looks back at the light.
#include <vector>

#include <glm/vec3.hpp>

#include "scene/material.h"
#include "scene/render_settings.h"

namespace gloss {

struct LobeParams {
  double elevation_deg = 45.0;    // light above the surface, degrees, 0 (grazing) .. 90 (overhead)
  double phong_alpha = 32.0;      // exponent of the Phong curve, >= 0
  double blinn_alpha = 32.0;      // exponent of the Blinn-Phong curve, >= 0
  bool energy_normalize = false;  // times (alpha + 2) / 2 pi (Phong), (alpha + 8) / 8 pi (Blinn)
  int samples = 181;              // outgoing angles from -90 to +90 degrees inclusive, >= 2
};

// Reflected radiance towards one outgoing direction, linear RGB, split by term.
struct LobeSample {
  double theta_deg = 0.0;   // outgoing angle from the normal (frame above)
  glm::dvec3 diffuse{0.0};  // kd * ndl: the same in every direction (the diffuse floor)
  glm::dvec3 phong{0.0};    // ks * c^alpha (* normalisation), c = R . V
  glm::dvec3 blinn{0.0};    // ks * c^alpha (* normalisation), c = N . H
  double cos_phong = 0.0;   // R . V, 0 where the light adds nothing
  double cos_blinn = 0.0;   // N . H, 0 where the light adds nothing
  // The material's physical reference under the same light, pi f(l, v) ndl
  // (docs/spec/physical-reference.md; physical/reference_brdf.h); 0 without one.
  glm::dvec3 reference{0.0};
};

struct BrdfLobe {
  LobeParams params;
  bool has_reference = false;  // the material has a physical reference (samples' `reference`)
  double phong_norm = 1.0, blinn_norm = 1.0;  // the energy factors applied (1 when off)
  std::vector<LobeSample> samples;            // params.samples of them, theta ascending
};

// One outgoing direction. theta_deg in [-90, 90].
LobeSample lobe_sample(const Material& material, const LobeParams& params, double theta_deg);

// The whole curve: params.samples directions evenly spaced over [-90, 90] degrees.
BrdfLobe sample_brdf_lobe(const Material& material, const LobeParams& params);

// Rec. 709 luminance of a linear RGB colour: the scalar the polar plot draws.
double luminance(const glm::dvec3& rgb);

}  // namespace gloss

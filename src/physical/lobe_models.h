#pragma once
// Lobes sampled over the pairs of physical/lobe_samples.h: the radiance a surface sends towards
// v under one light of unit colour from l (attenuation 1, visible), in the units of the shading
// contract, so a Phong lobe here is what the renderer computes and the reference is what it
// would add (pi f ndl).
#include <vector>

#include <glm/vec3.hpp>

#include "physical/lobe_samples.h"
#include "physical/reference_brdf.h"
#include "scene/material.h"
#include "scene/render_settings.h"

namespace gloss {

// Radiance per pair, linear RGB, in the order of LobeSamples::pairs.
using SampledLobe = std::vector<glm::dvec3>;

// A Phong or Blinn-Phong material as a lobe: kd ndl + ks N(alpha) c^alpha (shading.h), N the
// energy normalisation when switched on, else 1. ka and ke add no directional light.
struct PhongLobe {
  glm::dvec3 kd{0.0}, ks{0.0};
  double alpha = 0.0;
  ShadingModel model = ShadingModel::phong;
  bool energy_normalize = false;
};

PhongLobe phong_lobe(const Material& material, ShadingModel model, bool energy_normalize);

// One pair: the contract's diffuse and specular terms under the unit light.
glm::dvec3 phong_radiance(const PhongLobe& lobe, const LobePair& pair);
// The reference's pi f(l, v) n.l.
glm::dvec3 reference_radiance(const ReferenceBrdf& brdf, const LobePair& pair);

SampledLobe sample_phong(const PhongLobe& lobe, const LobeSamples& samples);
SampledLobe sample_reference(const ReferenceBrdf& brdf, const LobeSamples& samples);

}  // namespace gloss

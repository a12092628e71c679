#pragma once
// The environment light in the reference path (reference's own): at a hit, the contract's
// diffuse and specular terms in double. Shadows off, they are the unshadowed integrals of
// environment_quadrature.h, with their error bounds. Shadows on, they are estimates over
// `steps` directions drawn as the progressive renderer draws them (cosine, lobe and map with
// the balance heuristic, engine/environment/environment_sampling.h), each with its own shadow
// ray, and their standard errors; the unshadowed integrals come along, so the share of the
// irradiance that is visible (the inspector's `visibility`) is their ratio.
#include <functional>
#include <memory>

#include <glm/vec3.hpp>

#include "engine/environment/environment_sampling.h"
#include "reference/environment_quadrature.h"
#include "scene/scene.h"

namespace gloss {

struct ReferenceEnvironmentOptions {
  int steps = 1024;          // directions per hit for the shadowed estimate (3 rays each)
  double tolerance = 1e-3;   // relative error bound of the unshadowed integrals
  // true: every unshadowed integral by the bounded cubature (the inspector); false: the
  // specular term above alpha 16 by the texel sum (lobe_sum.h; images), without a bound.
  bool bounded = false;
};

class ReferenceEnvironment {
 public:
  ReferenceEnvironment(const Scene& scene, const ReferenceEnvironmentOptions& options);
  bool present() const { return m_environment != nullptr; }

  // What one hit receives, intensity included, before kd and ks.
  struct Reading {
    glm::dvec3 diffuse{0.0}, specular{0.0};          // the contract's terms / kd, / ks
    glm::dvec3 diffuse_error{0.0}, specular_error{0.0};  // bound (shadows off) or standard error
    glm::dvec3 unshadowed_diffuse{0.0}, unshadowed_specular{0.0};
    double visibility = 1.0;  // visible share of the irradiance (luminance), 1 without shadows
    bool estimated = false;   // shadows on: an estimate with an error bar, not a bound
  };

  // n, v unit on the viewer's side; alpha, model of the material; blocked(w) whether the ray
  // from the hit's shadow origin towards world direction w meets a surface (shadows on only).
  // seed: decorrelates the draws of different samples.
  Reading at(const glm::dvec3& n, const glm::dvec3& v, double alpha, ShadingModel model,
             bool diffuse, bool specular, bool shadows, std::uint32_t seed,
             const std::function<bool(const glm::dvec3&)>& blocked) const;

  // The map's radiance towards world direction d, intensity included (the background).
  glm::dvec3 radiance(const glm::dvec3& d) const;

 private:
  const Environment* m_environment = nullptr;
  ReferenceEnvironmentOptions m_options;
  EnvironmentRotation<double> m_rotation;
  std::shared_ptr<const EnvironmentQuadrature> m_quadrature;
  std::unique_ptr<EnvironmentSampler> m_sampler;
};

}  // namespace gloss

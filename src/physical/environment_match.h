#pragma once
// What the shading contract's environment light asks of a Phong material standing in for a
// reference (docs/spec/shading.md, "Environment light"): there the specular term is ks times
// the *normalised* lobe's average of L, so ks is a reflectance, compared with the reference's
// directional albedo directly (about F0 for a smooth metal seen head-on), and alpha only blurs.
// The point-light fit (physical/phong_fit.h) answers a different question: its ks carries the
// highlight's peak. Written with the contract's formula; no environment is rendered here.
#include <glm/vec3.hpp>

#include "physical/reference_brdf.h"
#include "scene/render_settings.h"

namespace gloss {

struct EnvironmentMatch {
  glm::dvec3 albedo_normal{0.0};   // directional albedo seen head-on (v = n)
  glm::dvec3 albedo_grazing{0.0};  // ... at 80 degrees from the normal
  // The cosine-weighted mean over view directions: what a uniform environment of radiance 1
  // reflects on average, and so the ks (and the ka under a uniform ambient) to use.
  glm::dvec3 albedo_mean{0.0};
  double alpha = 0.0;     // exponent whose normalised lobe is closest to the reference's
                          // reflected lobe head-on (l2 over the hemisphere)
  double residual = 0.0;  // that lobe match's l2, relative to the reference lobe's own
};

// The albedos and the environment exponent of a reference, for the Phong or Blinn-Phong lobe.
EnvironmentMatch match_environment(const ReferenceBrdf& brdf, ShadingModel model);

}  // namespace gloss

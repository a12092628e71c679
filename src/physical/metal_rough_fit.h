#pragma once
// glTF 2.0's metallic-roughness material (the core specification's Appendix B: GGX, the
// height-correlated Smith term and Schlick's Fresnel, a dielectric of F0 = 0.04 over a Lambertian
// base mixed with a conductor of F0 = base colour by `metallic`), and the fit "the other way":
// the metallic-roughness material whose lobe comes closest to a Phong or Blinn-Phong lobe, over
// the light-view pairs and in the metrics of the Phong fit (physical/phong_fit.h).
//
//   F(v.h)  = F0 + (1 - F0) (1 - v.h)^5,   F0 = mix(0.04, base, metallic)
//   f       = F D G2 / (4 n.l n.v) + (1 - metallic) (1 - F_0.04(v.h)) base / pi
//   radiance under a unit light of the shading contract: pi f n.l (physical/lobe_models.h)
//
// For fixed metallic and roughness the radiance is affine in the base colour (A + base B per
// pair), so a scan over (metallic, roughness) solves the base colour exactly per channel (l2,
// clamped to [0, 1]); Levenberg-Marquardt then refines all five in the chosen metric.
#include <glm/vec3.hpp>

#include "physical/lobe_metrics.h"
#include "physical/lobe_models.h"
#include "physical/lobe_samples.h"
#include "physical/phong_fit.h"

namespace gloss {

// The smallest roughness the fit gives: a = 1e-6, a mirror for every exponent up to 1e6.
inline constexpr double kMinFitRoughness = 1e-3;

struct MetalRough {
  glm::dvec3 base_colour{1.0};  // linear RGB in [0, 1]
  double metallic = 1.0;        // [0, 1]
  double roughness = 1.0;       // perceptual, (0, 1]; GGX a = roughness^2
};

// pi f n.l for one pair (0 where the pair is below the surface).
glm::dvec3 metal_rough_radiance(const MetalRough& material, const LobePair& pair);
SampledLobe sample_metal_rough(const MetalRough& material, const LobeSamples& samples);

struct MetalRoughFit {
  MetalRough material;
  LobeResidual residual;  // against the Phong lobe, both metrics
  int iterations = 0;     // Levenberg-Marquardt iterations
  int pairs = 0;
};

// The metallic-roughness material closest to source (its model and energy switch as given),
// minimising metric over the grid (its width set from the source's exponent).
MetalRoughFit fit_metal_rough(const PhongLobe& source, LobeMetric metric = LobeMetric::l2,
                              LobeGrid grid = {});

// The same over given samples and target (tests, and callers that sample once).
MetalRoughFit fit_metal_rough_lobe(const LobeSamples& samples, const SampledLobe& target,
                                   LobeMetric metric);

// Import the other way: the Phong or Blinn-Phong lobe closest to a metallic-roughness
// material (the Phong fit of physical/phong_fit.h with the glTF lobe as its target; ka and ke
// are not part of it). The fit runs on a coarser grid (an eighth of the pairs), its residual is
// measured on the full grid of width from the material's GGX a.
PhongFit fit_phong_to_metal_rough(const MetalRough& material, const FitOptions& options = {});

// How far a given Phong lobe is from a metallic-roughness material, on that full grid (what an
// importer's rule of thumb costs).
LobeResidual residual_to_metal_rough(const PhongLobe& lobe, const MetalRough& material);

// The grid a Phong or Blinn-Phong lobe is compared on (width from its exponent: a Phong lobe of
// exponent alpha is about as wide as a Blinn-Phong lobe of 4 alpha).
LobeGrid grid_for_phong(const PhongLobe& lobe, LobeGrid grid = {});

}  // namespace gloss

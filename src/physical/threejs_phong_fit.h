#pragma once
// three.js's MeshPhongMaterial as a lobe, and the constants that bring it closest to a gloss
// Phong or Blinn-Phong lobe. three.js's "Phong" is not the classic model: its documentation
// calls it Blinn-Phong, and its shader (bsdfs: BRDF_BlinnPhong, D_BlinnPhong,
// G_BlinnPhong_Implicit, F_Schlick) computes, for a light of colour E,
//
//   diffuse  = E n.l color / pi
//   specular = E n.l F(specular, v.h) G D,  G = 1/4,  D = (shininess / 2 + 1) / pi (n.h)^shininess
//   F(f0, v.h) = f0 + (1 - f0) 2^((-5.55473 v.h - 6.98316) v.h)   (Schlick, as its shader
//                                                                  approximates the 5th power)
//
// A light of intensity pi in three.js (its physically based units; the legacy mode multiplied by
// pi itself) therefore gives n.l (color + F (shininess / 2 + 1) / 4 (n.h)^shininess), the units
// of gloss's lobes (physical/lobe_models.h). color and specular are in [0, 1] (the JSON keeps
// them as 8-bit hex); shininess >= 0.
#include <glm/vec3.hpp>

#include "physical/lobe_metrics.h"
#include "physical/lobe_models.h"
#include "physical/lobe_samples.h"

namespace gloss {

struct ThreePhong {
  glm::dvec3 color{1.0};     // linear RGB, [0, 1]
  glm::dvec3 specular{0.0};  // Schlick's F0, linear RGB, [0, 1]
  double shininess = 30.0;
};

// three.js's Schlick approximation, 2^((-5.55473 x - 6.98316) x) for x = v.h in [0, 1].
double threejs_fresnel_weight(double vdh);

glm::dvec3 threejs_phong_radiance(const ThreePhong& material, const LobePair& pair);
SampledLobe sample_threejs_phong(const ThreePhong& material, const LobeSamples& samples);

struct ThreePhongFit {
  ThreePhong material;
  LobeResidual residual;
  int iterations = 0;
  int pairs = 0;
};

// The three.js constants closest to source (its diffuse and specular together) in metric.
ThreePhongFit fit_threejs_phong(const PhongLobe& source, LobeMetric metric = LobeMetric::l2,
                                LobeGrid grid = {});
// The same over given samples and target.
ThreePhongFit fit_threejs_phong_lobe(const LobeSamples& samples, const SampledLobe& target,
                                     LobeMetric metric);

}  // namespace gloss

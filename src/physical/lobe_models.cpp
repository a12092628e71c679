#include "physical/lobe_models.h"

#include "physical/microfacet.h"
#include "shading/shading.h"

namespace gloss {

PhongLobe phong_lobe(const Material& material, ShadingModel model, bool energy_normalize) {
  PhongLobe lobe;
  lobe.kd = glm::dvec3(material.diffuse);
  lobe.ks = glm::dvec3(material.specular);
  lobe.alpha = material.shininess;
  lobe.model = model;
  lobe.energy_normalize = energy_normalize;
  return lobe;
}

glm::dvec3 phong_radiance(const PhongLobe& lobe, const LobePair& pair) {
  const double c = lobe.model == ShadingModel::phong ? pair.cos_phong : pair.cos_blinn;
  const double norm = lobe.energy_normalize ? energy_normalization(lobe.model, lobe.alpha) : 1.0;
  return lobe.kd * pair.angles.ndl + lobe.ks * (norm * specular_power(c, lobe.alpha));
}

glm::dvec3 reference_radiance(const ReferenceBrdf& brdf, const LobePair& pair) {
  return evaluate_brdf(brdf, pair.angles).total() * (kPi * pair.angles.ndl);
}

SampledLobe sample_phong(const PhongLobe& lobe, const LobeSamples& samples) {
  SampledLobe out;
  out.reserve(samples.pairs.size());
  for (const LobePair& pair : samples.pairs) out.push_back(phong_radiance(lobe, pair));
  return out;
}

SampledLobe sample_reference(const ReferenceBrdf& brdf, const LobeSamples& samples) {
  SampledLobe out;
  out.reserve(samples.pairs.size());
  for (const LobePair& pair : samples.pairs) out.push_back(reference_radiance(brdf, pair));
  return out;
}

}  // namespace gloss

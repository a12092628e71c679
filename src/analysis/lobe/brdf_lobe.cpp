#include "analysis/lobe/brdf_lobe.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "physical/reference_brdf.h"
#include "shading/shading.h"

namespace gloss {

namespace {

constexpr double kPi = 3.14159265358979323846;

double radians(double degrees) {
  return degrees * kPi / 180.0;
}

}  // namespace

LobeSample lobe_sample(const Material& material, const LobeParams& params, double theta_deg) {
  using V = glm::dvec3;
  const double e = radians(params.elevation_deg), t = radians(theta_deg);
  const V p(0.0), n(0.0, 1.0, 0.0);
  const V v(std::sin(t), std::cos(t), 0.0);
  // A point light one unit away with unit attenuation is a light from direction l.
  const V light(-std::cos(e), std::sin(e), 0.0);
  const LightFactors<double> f = light_factors<double>(p, n, v, light, V(1.0, 0.0, 0.0), true, 1.0);
  LobeSample s;
  s.theta_deg = theta_deg;
  s.cos_phong = f.cos_phong;
  s.cos_blinn = f.cos_blinn;
  const V kd(material.diffuse), ks(material.specular);
  s.diffuse = kd * f.diffuse_weight;
  const double phong_norm =
      params.energy_normalize ? energy_normalization(ShadingModel::phong, params.phong_alpha) : 1.0;
  const double blinn_norm =
      params.energy_normalize ? energy_normalization(ShadingModel::blinn_phong, params.blinn_alpha)
                              : 1.0;
  s.phong = ks * (f.spec_weight * specular_power(f.cos_phong, params.phong_alpha) * phong_norm);
  s.blinn = ks * (f.spec_weight * specular_power(f.cos_blinn, params.blinn_alpha) * blinn_norm);
  if (material.reference && f.diffuse_weight > 0.0) {
    const glm::dvec3 l = glm::normalize(light);
    s.reference = evaluate_brdf(make_reference_brdf(*material.reference), n, l, v).total() *
                  (kPi * f.diffuse_weight);
  }
  return s;
}

BrdfLobe sample_brdf_lobe(const Material& material, const LobeParams& params) {
  BrdfLobe lobe;
  lobe.params = params;
  lobe.params.samples = std::max(params.samples, 2);
  lobe.has_reference = material.reference.has_value();
  if (params.energy_normalize) {
    lobe.phong_norm = energy_normalization(ShadingModel::phong, params.phong_alpha);
    lobe.blinn_norm = energy_normalization(ShadingModel::blinn_phong, params.blinn_alpha);
  }
  const int count = lobe.params.samples;
  lobe.samples.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double theta = -90.0 + 180.0 * static_cast<double>(i) / (count - 1);
    lobe.samples.push_back(lobe_sample(material, params, theta));
  }
  return lobe;
}

double luminance(const glm::dvec3& rgb) {
  return 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z;
}

}  // namespace gloss

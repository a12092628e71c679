#include "reference/reference_environment.h"

#include <glm/geometric.hpp>

#include "shading/sampling.h"

namespace gloss {

ReferenceEnvironment::ReferenceEnvironment(const Scene& scene,
                                           const ReferenceEnvironmentOptions& options)
    : m_options(options) {
  if (!scene.environment.present()) return;
  m_environment = &scene.environment;
  m_rotation = environment_rotation<double>(scene.environment.rotation);
  m_quadrature = environment_quadrature(scene.environment.map);
  if (scene.render.shadows) m_sampler = std::make_unique<EnvironmentSampler>(*scene.environment.map);
}

glm::dvec3 ReferenceEnvironment::radiance(const glm::dvec3& d) const {
  return environment_radiance<double>(*m_environment, m_rotation, d);
}

ReferenceEnvironment::Reading ReferenceEnvironment::at(
    const glm::dvec3& n, const glm::dvec3& v, double alpha, ShadingModel model, bool diffuse,
    bool specular, bool shadows, std::uint32_t seed,
    const std::function<bool(const glm::dvec3&)>& blocked) const {
  Reading out;
  const double intensity = m_environment->intensity;
  const glm::dvec3 r = 2.0 * glm::dot(n, v) * n - v;
  const glm::dvec3 nm = to_map_frame(n, m_rotation), vm = to_map_frame(v, m_rotation),
                   rm = to_map_frame(r, m_rotation);
  if (diffuse) {
    const QuadratureResult d = m_quadrature->diffuse(nm, m_options.tolerance);
    out.unshadowed_diffuse = d.value * intensity;
    out.diffuse_error = d.bound * intensity;
  }
  if (specular && (m_options.bounded || alpha <= 16.0)) {
    const QuadratureResult s = m_quadrature->specular(model, nm, vm, rm, alpha, m_options.tolerance);
    out.unshadowed_specular = s.value * intensity;
    out.specular_error = s.bound * intensity;
  } else if (specular) {
    out.unshadowed_specular = m_quadrature->specular_sum(model, nm, vm, rm, alpha) * intensity;
  }
  out.diffuse = out.unshadowed_diffuse;
  out.specular = out.unshadowed_specular;
  if (!shadows || m_sampler == nullptr || (!diffuse && !specular)) return out;

  EnvironmentHit hit;
  hit.n = n;
  hit.v = v;
  hit.r = r;
  hit.alpha = alpha;
  hit.model = model;
  hit.diffuse = diffuse;
  hit.specular = specular;
  EnvironmentSums sums;
  for (int step = 0; step < m_options.steps; ++step) {
    double u[6];
    std::uint32_t h = mix_bits(seed ^ mix_bits(static_cast<std::uint32_t>(step) + 0x632be5abU));
    for (double& x : u) {
      h = mix_bits(h + 0x9e3779b9U);
      x = (static_cast<double>(h >> 5) + 0.5) * (1.0 / 134217728.0);
    }
    const EnvironmentDraws draws = environment_draws(hit, *m_environment, m_rotation, *m_sampler, u);
    bool visible[EnvironmentDraws::kCount];
    for (int k = 0; k < EnvironmentDraws::kCount; ++k) {
      visible[k] = draws.carries[k] && !blocked(draws.w[k]);
    }
    add_draws(draws, visible, sums);
  }
  out.estimated = true;
  out.diffuse = sums.diffuse.value() * intensity;
  out.specular = sums.specular.value() * intensity;
  out.diffuse_error = sums.diffuse.error(sums.steps) * intensity;
  out.specular_error = sums.specular.error(sums.steps) * intensity;
  const double lum_shadowed = out.diffuse.x + out.diffuse.y + out.diffuse.z;
  const double lum_open = out.unshadowed_diffuse.x + out.unshadowed_diffuse.y + out.unshadowed_diffuse.z;
  out.visibility = lum_open > 0.0 ? std::min(1.0, lum_shadowed / lum_open) : 1.0;
  return out;
}

}  // namespace gloss

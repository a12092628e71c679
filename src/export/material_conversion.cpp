#include "export/material_conversion.h"

#include <cstdio>

#include <glm/common.hpp>

#include <tbb/parallel_for.h>
#include <nlohmann/json.hpp>

namespace gloss {

namespace {

std::string colour_text(const glm::dvec3& c) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.3g, %.3g, %.3g)", c.x, c.y, c.z);
  return text;
}

std::string residual_text(const LobeResidual& r) {
  char text[96];
  std::snprintf(text, sizeof text, "residual %.3g %% (l2 %.3g, L* %.3g)", 100.0 * r.l2_relative,
                r.l2, r.lightness);
  return text;
}

nlohmann::json residual_json(const LobeResidual& r) {
  return {{"l2", r.l2}, {"l2_relative", r.l2_relative}, {"lightness", r.lightness}};
}

nlohmann::json colour_json(const glm::dvec3& c) {
  return nlohmann::json::array({c.x, c.y, c.z});
}

}  // namespace

MaterialConversion convert_material(const std::string& name, const Material& material,
                                    ShadingModel model, bool energy_normalize) {
  MaterialConversion out;
  out.name = name;
  out.source = phong_lobe(material, model, energy_normalize);
  // The fits run over a coarser grid than the residuals are measured on (an eighth of the
  // pairs: about 4000); on gold's lobe the fitted material's error on the full grid moved by
  // 2e-5 of 0.119 (docs/export.md), at a seventh of the time.
  LobeGrid coarse;
  coarse.per_decade = 10;
  coarse.even = 8;
  coarse.theta_d = 10;
  coarse.phi_d = 10;
  const LobeSamples fit_samples = make_lobe_samples(grid_for_phong(out.source, coarse));
  const SampledLobe fit_source = sample_phong(out.source, fit_samples);
  out.gltf = fit_metal_rough_lobe(fit_samples, fit_source, LobeMetric::l2);
  if (out.source.ks == glm::dvec3(0.0)) {
    // No highlight: at shininess 0 three.js's specular term is n.l F / 4, a second diffuse
    // term, so color + specular can match kd in many ways (the fit finds specular 1); the one a
    // user expects is specular 0 (its Fresnel still adds a faint grazing term, in the residual).
    out.threejs.material = {glm::clamp(out.source.kd, 0.0, 1.0), glm::dvec3(0.0), 0.0};
  } else {
    out.threejs = fit_threejs_phong_lobe(fit_samples, fit_source, LobeMetric::l2);
  }
  FitOptions options;
  options.model = model;
  options.energy_normalize = energy_normalize;
  out.gltf_back =
      fit_phong_lobe(fit_samples, sample_metal_rough(out.gltf.material, fit_samples), options).lobe;

  // Every residual on the full grid of the Phong fit (physical/lobe_samples.h's defaults).
  const LobeSamples samples = make_lobe_samples(grid_for_phong(out.source));
  const SampledLobe source = sample_phong(out.source, samples);
  out.gltf.residual =
      lobe_residual(samples, source, sample_metal_rough(out.gltf.material, samples));
  out.threejs.residual =
      lobe_residual(samples, source, sample_threejs_phong(out.threejs.material, samples));
  out.round_trip = lobe_residual(samples, source, sample_phong(out.gltf_back, samples));
  out.gltf.pairs = out.threejs.pairs = static_cast<int>(samples.pairs.size());
  return out;
}

std::vector<MaterialConversion> convert_materials(const Scene& scene) {
  std::vector<MaterialConversion> out(scene.materials.size());
  tbb::parallel_for(std::size_t(0), out.size(), [&](std::size_t i) {
    const std::string name =
        i < scene.material_names.size() ? scene.material_names[i] : "material" + std::to_string(i);
    out[i] = convert_material(name, scene.materials[i], scene.render.model,
                              scene.render.energy_normalize);
  });
  return out;
}

std::vector<std::string> conversion_lines(const std::vector<MaterialConversion>& conversions) {
  std::vector<std::string> lines;
  for (const MaterialConversion& c : conversions) {
    char text[160];
    const MetalRough& g = c.gltf.material;
    std::snprintf(text, sizeof text, " metallic %.3g roughness %.3g, ", g.metallic, g.roughness);
    lines.push_back(c.name + ": glTF base " + colour_text(g.base_colour) + text +
                    residual_text(c.gltf.residual));
    const ThreePhong& t = c.threejs.material;
    std::snprintf(text, sizeof text, " shininess %.4g, ", t.shininess);
    lines.push_back(c.name + ": three.js color " + colour_text(t.color) + " specular " +
                    colour_text(t.specular) + text + residual_text(c.threejs.residual));
    std::snprintf(text, sizeof text, " alpha %.4g, ", c.gltf_back.alpha);
    lines.push_back(c.name + ": Phong -> glTF -> Phong kd " + colour_text(c.gltf_back.kd) + " ks " +
                    colour_text(c.gltf_back.ks) + text + residual_text(c.round_trip));
  }
  return lines;
}

std::string conversion_json(const std::vector<MaterialConversion>& conversions) {
  nlohmann::json materials = nlohmann::json::array();
  for (const MaterialConversion& c : conversions) {
    const MetalRough& g = c.gltf.material;
    const ThreePhong& t = c.threejs.material;
    materials.push_back({{"name", c.name},
                         {"phong",
                          {{"kd", colour_json(c.source.kd)},
                           {"ks", colour_json(c.source.ks)},
                           {"shininess", c.source.alpha},
                           {"model", to_string(c.source.model)},
                           {"energy_normalize", c.source.energy_normalize}}},
                         {"gltf",
                          {{"base_colour", colour_json(g.base_colour)},
                           {"metallic", g.metallic},
                           {"roughness", g.roughness},
                           {"residual", residual_json(c.gltf.residual)}}},
                         {"threejs_phong",
                          {{"color", colour_json(t.color)},
                           {"specular", colour_json(t.specular)},
                           {"shininess", t.shininess},
                           {"residual", residual_json(c.threejs.residual)}}},
                         {"round_trip",
                          {{"kd", colour_json(c.gltf_back.kd)},
                           {"ks", colour_json(c.gltf_back.ks)},
                           {"shininess", c.gltf_back.alpha},
                           {"residual", residual_json(c.round_trip)}}}});
  }
  return nlohmann::json{{"materials", materials}}.dump(2) + "\n";
}

}  // namespace gloss

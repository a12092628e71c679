#include "export/threejs_export.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "base/version.h"

namespace gloss {

namespace {

using nlohmann::json;

int hex(const glm::dvec3& linear) {
  return (srgb_byte(linear.x) << 16) | (srgb_byte(linear.y) << 8) | srgb_byte(linear.z);
}

json linear(const glm::dvec3& c) {
  return json::array({c.x, c.y, c.z});
}

json residual(const LobeResidual& r) {
  return {{"l2", r.l2}, {"l2_relative", r.l2_relative}, {"lightness", r.lightness}};
}

}  // namespace

int srgb_byte(double linear) {
  const double x = std::clamp(linear, 0.0, 1.0);
  const double encoded = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
  return static_cast<int>(std::lround(encoded * 255.0));
}

std::string threejs_materials_json(const Scene& scene,
                                   const std::vector<MaterialConversion>& conversions) {
  json materials = json::array();
  for (std::size_t i = 0; i < conversions.size() && i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    const MaterialConversion& c = conversions[i];
    const glm::dvec3 ke(m.emission);
    json maps = json::object();
    for (int s = 0; s < kMapSlots; ++s) {
      const TextureMap& map = m.map(static_cast<MapSlot>(s));
      if (map.named()) maps[to_string(static_cast<MapSlot>(s))] = map.file;
    }
    const json gloss = {{"ambient", linear(glm::dvec3(m.ambient))},
                        {"diffuse", linear(c.source.kd)},
                        {"specular", linear(c.source.ks)},
                        {"emission", linear(ke)},
                        {"shininess", c.source.alpha},
                        {"model", to_string(c.source.model)},
                        {"energy_normalize", c.source.energy_normalize},
                        {"maps", maps}};
    const ThreePhong& t = c.threejs.material;
    materials.push_back(
        {{"uuid", "gloss-phong-" + std::to_string(i)},
         {"type", "MeshPhongMaterial"},
         {"name", c.name},
         {"color", hex(t.color)},
         {"specular", hex(t.specular)},
         {"shininess", t.shininess},
         {"emissive", hex(ke)},
         {"userData",
          {{"linear",
            {{"color", linear(t.color)},
             {"specular", linear(t.specular)},
             {"emissive", linear(ke)}}},
           {"residual", residual(c.threejs.residual)},
           {"lights", "gloss's radiance with three.js lights of intensity pi (physical units)"},
           {"gloss", gloss}}}});
    const MetalRough& g = c.gltf.material;
    materials.push_back(
        {{"uuid", "gloss-standard-" + std::to_string(i)},
         {"type", "MeshStandardMaterial"},
         {"name", c.name},
         {"color", hex(g.base_colour)},
         {"metalness", g.metallic},
         {"roughness", g.roughness},
         {"emissive", hex(ke)},
         {"userData",
          {{"linear", {{"color", linear(g.base_colour)}, {"emissive", linear(ke)}}},
           {"residual", residual(c.gltf.residual)},
           {"lights", "gloss's radiance with three.js lights of intensity pi (physical units)"},
           {"gloss", gloss}}}});
  }
  const json doc = {{"metadata",
                     {{"version", 4.6},
                      {"type", "Material"},
                      {"generator", std::string("gloss ") + gloss_version()}}},
                    {"materials", materials}};
  return doc.dump(2) + "\n";
}

}  // namespace gloss

#include "export/threejs_export.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "base/version.h"
#include "export/threejs_maps.h"

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

ThreejsExport threejs_export(const Scene& scene, const std::vector<MaterialConversion>& conversions,
                             const std::string& out_path) {
  ThreejsMaps maps(scene, out_path);
  json materials = json::array(), children = json::array();
  // A unit sphere per material and kind, 2.5 apart: column i, the Phong row at y = 0, the
  // Standard row at y = -2.5 (column-major matrices, translation in elements 12 to 14).
  const auto sphere = [&children](const json& material, double x, double y) {
    json matrix = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, y, 0, 1};
    children.push_back({{"uuid", "gloss-mesh-" + std::to_string(children.size())},
                        {"type", "Mesh"},
                        {"name", material["name"].get<std::string>() + " (" +
                                     material["type"].get<std::string>() + ")"},
                        {"geometry", "gloss-sphere"},
                        {"material", material["uuid"]},
                        {"matrix", matrix}});
  };
  for (std::size_t i = 0; i < conversions.size() && i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    const MaterialConversion& c = conversions[i];
    const glm::dvec3 ke(m.emission);
    json names = json::object();
    for (int s = 0; s < kMapSlots; ++s) {
      const TextureMap& map = m.map(static_cast<MapSlot>(s));
      if (map.named()) names[to_string(static_cast<MapSlot>(s))] = map.file;
    }
    const json gloss = {{"ambient", linear(glm::dvec3(m.ambient))},
                        {"diffuse", linear(c.source.kd)},
                        {"specular", linear(c.source.ks)},
                        {"emission", linear(ke)},
                        {"shininess", c.source.alpha},
                        {"model", to_string(c.source.model)},
                        {"energy_normalize", c.source.energy_normalize},
                        {"maps", names}};
    const ThreePhong& t = c.threejs.material;
    json phong = {
        {"uuid", "gloss-phong-" + std::to_string(i)},
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
          {"gloss", gloss}}}};
    phong.update(maps.material_fields(i, c.name, true));
    const MetalRough& g = c.gltf.material;
    json standard = {
        {"uuid", "gloss-standard-" + std::to_string(i)},
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
          {"gloss", gloss}}}};
    standard.update(maps.material_fields(i, c.name, false));
    sphere(phong, 2.5 * static_cast<double>(i), 0.0);
    sphere(standard, 2.5 * static_cast<double>(i), -2.5);
    materials.push_back(phong);
    materials.push_back(standard);
  }
  json doc = {{"metadata",
               {{"version", 4.6},
                {"type", "Object"},
                {"generator", std::string("gloss ") + gloss_version()}}},
              {"geometries",
               {{{"uuid", "gloss-sphere"},
                 {"type", "SphereGeometry"},
                 {"radius", 1},
                 {"widthSegments", 64},
                 {"heightSegments", 32}}}},
              {"materials", materials},
              {"object",
               {{"uuid", "gloss-scene"},
                {"type", "Scene"},
                {"name", "gloss materials"},
                {"children", children}}}};
  if (!maps.images.empty()) doc["images"] = maps.images;
  if (!maps.textures.empty()) doc["textures"] = maps.textures;
  return {doc.dump(2) + "\n", maps.notices};
}

}  // namespace gloss

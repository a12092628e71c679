#pragma once
// What a Phong material becomes outside gloss, with the error of each conversion measured
// (docs/export.md): the glTF metallic-roughness material closest to its lobe, three.js's
// MeshPhongMaterial closest to it, and the round trips.
//
// The lobe compared is the one the scene renders: its shading model and energy switch under a
// unit light (physical/lobe_models.h), kd and ks only (ka and ke add no directional light; ka has
// no place in glTF or three.js and travels in extras, ke is the emissive colour as it is).
// Errors are the Phong fit's metrics (physical/lobe_metrics.h): l2 in radiance (a white
// Lambertian head-on sends 1), l2 relative to the lobe's own size, and CIE L*.
#include <string>
#include <vector>

#include "physical/lobe_metrics.h"
#include "physical/metal_rough_fit.h"
#include "physical/phong_fit.h"
#include "physical/threejs_phong_fit.h"
#include "scene/scene.h"

namespace gloss {

struct MaterialConversion {
  std::string name;
  PhongLobe source;         // the lobe the scene renders
  MetalRoughFit gltf;       // glTF's metallic-roughness fit, residual against source
  ThreePhongFit threejs;    // three.js MeshPhongMaterial fit, residual against source
  PhongLobe gltf_back;      // the Phong lobe fitted back to gltf (what an importer reading
                            // the PBR values alone, without extras, gets: see io/model)
  LobeResidual round_trip;  // gltf_back against source: Phong -> PBR -> Phong
};

// One material; model and energy switch as the scene renders them.
MaterialConversion convert_material(const std::string& name, const Material& material,
                                    ShadingModel model, bool energy_normalize);

// Every material of the scene, in its order (in parallel: each fit alone, the same bits).
std::vector<MaterialConversion> convert_materials(const Scene& scene);

// One line per material: "gold: glTF base (1, 0.78, 0.34) metallic 1 roughness 0.31,
// residual 4.1 % (l2 0.012, L* 1.3); three.js ...; round trip ...".
std::vector<std::string> conversion_lines(const std::vector<MaterialConversion>& conversions);

// The same as a JSON text ({"materials": [...]}), for --json.
std::string conversion_json(const std::vector<MaterialConversion>& conversions);

}  // namespace gloss

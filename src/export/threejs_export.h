#pragma once
// A scene's materials for three.js (docs/export.md): each as a MeshPhongMaterial whose colour,
// specular and shininess are fitted to three.js's own Phong formula
// (physical/threejs_phong_fit.h), and as a MeshStandardMaterial from the glTF fit, in the JSON
// three.js's MaterialLoader reads (one entry of `materials` each: MaterialLoader().parse(entry)).
// Colours are written as three.js writes them, sRGB-encoded 8-bit hex; the exact linear values,
// the gloss constants and the fits' residuals are in each material's userData. Maps are named in
// userData, not loaded as three.js textures.
#include <string>
#include <vector>

#include "export/material_conversion.h"
#include "scene/scene.h"

namespace gloss {

// The JSON text.
std::string threejs_materials_json(const Scene& scene,
                                   const std::vector<MaterialConversion>& conversions);

// A linear colour component as three.js's 8-bit sRGB hex channel (clamped to [0, 1]).
int srgb_byte(double linear);

}  // namespace gloss

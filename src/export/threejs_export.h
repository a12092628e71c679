#pragma once
// A scene's materials for three.js (docs/export.md): each as a MeshPhongMaterial whose colour,
// specular and shininess are fitted to three.js's own Phong formula
// (physical/threejs_phong_fit.h), and as a MeshStandardMaterial from the glTF fit, in three.js's
// JSON Object format (ObjectLoader().parse(json) gives a Scene with one unit sphere per material
// and kind, in a row, Phong above Standard). Maps are three.js textures (export/threejs_maps.h)
// whose images are referred to by URLs relative to the JSON file. Colours are written as three.js
// writes them, sRGB-encoded 8-bit hex; the exact linear values, the gloss constants and the
// fits' residuals are in each material's userData.
#include <string>
#include <vector>

#include "export/material_conversion.h"
#include "scene/scene.h"

namespace gloss {

struct ThreejsExport {
  std::string json;  // the file's text
  // What three.js cannot take, or takes otherwise ("material 'wood': shininess map not carried
  // to three.js: ..."), one line each.
  std::vector<std::string> notices;
};

// out_path: where the JSON will be written (the images' URLs are relative to its folder).
ThreejsExport threejs_export(const Scene& scene, const std::vector<MaterialConversion>& conversions,
                             const std::string& out_path);

// A linear colour component as three.js's 8-bit sRGB hex channel (clamped to [0, 1]).
int srgb_byte(double linear);

}  // namespace gloss

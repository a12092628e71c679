#pragma once
// A scene as glTF 2.0 (docs/export.md): its objects' triangles (spheres tessellated), the camera,
// the lights as KHR_lights_punctual (point, directional, spot with its cone) and each material
// as the metallic-roughness material fitted to its lobe (export/material_conversion.h), with the
// exact Phong constants in the material's `extras.gloss`, which gloss's model reader takes
// back exactly (io/model). Diffuse, normal and emission maps become the base colour, normal and
// emissive textures, a scaled, turned or moved map with KHR_texture_transform
// (export/map_export.h).
//
// Written by hand with nlohmann-json, not through assimp's exporter: assimp's glTF 2.0 exporter
// writes neither KHR_lights_punctual nor material extras, which carry the lights and the exact
// constants.
#include <string>
#include <vector>

#include "export/material_conversion.h"
#include "scene/scene.h"

namespace gloss {

struct GltfExportOptions {
  int sphere_segments = 64;  // around a sphere's equator (half as many pole to pole)
};

struct GltfExportResult {
  // What the file could not carry, one line each ("material 'wood': specular map not carried:
  // glTF has no slot for it").
  std::vector<std::string> notices;
  std::size_t bytes = 0;  // the file's size (with its .bin for .gltf)
};

// Whether path ends in .gltf or .glb (case-insensitive).
bool is_gltf_path(const std::string& path);

// Writes scene to path: .gltf (JSON, with its buffer in PATH_STEM.bin beside it) or .glb (one
// binary file with the images inside). conversions: convert_materials(scene). Nothing is left
// behind on failure. Throws InputError (file = path) for another extension or a map image that
// cannot be read, RuntimeFailure when it cannot write.
GltfExportResult export_gltf(const Scene& scene, const std::vector<MaterialConversion>& conversions,
                             const std::string& path, const GltfExportOptions& options = {});

}  // namespace gloss

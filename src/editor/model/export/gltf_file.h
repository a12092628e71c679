#pragma once
// File > Export glTF and the script line `export gltf PATH` (issue 26): the scene written by
// export/gltf_export.h with every material's conversion (export/material_conversion.h), and the
// summary the status bar shows: each material's fitted roughness and metallic and how far the
// glTF material is from the Phong one. GL-free.
#include <string>

#include "scene/scene.h"

namespace gloss {

// Writes scene to path (.gltf or .glb); print_lines: also prints every conversion line and the
// file's notices on stdout (scripts). Returns "exported PATH: gold roughness 0.71 metallic 0.05
// error 11.8 % (L* 2.9), ...": the glTF fit's residual, l2 relative and L*. Throws what
// export_gltf throws.
std::string write_gltf_file(const Scene& scene, const std::string& path, bool print_lines);

}  // namespace gloss

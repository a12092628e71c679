#include "editor/model/export/gltf_file.h"

#include <cstdio>

#include "export/gltf_export.h"
#include "export/material_conversion.h"

namespace gloss {

std::string write_gltf_file(const Scene& scene, const std::string& path, bool print_lines) {
  const std::vector<MaterialConversion> conversions = convert_materials(scene);
  const GltfExportResult result = export_gltf(scene, conversions, path);
  if (print_lines) {
    for (const std::string& line : conversion_lines(conversions)) std::printf("%s\n", line.c_str());
    for (const std::string& notice : result.notices) std::printf("note: %s\n", notice.c_str());
  }
  std::string summary = "exported " + path + ":";
  for (std::size_t i = 0; i < conversions.size(); ++i) {
    const MaterialConversion& c = conversions[i];
    char text[160];
    std::snprintf(text, sizeof text, " %s roughness %.2f metallic %.2f error %.1f %% (L* %.2g)%s",
                  c.name.c_str(), c.gltf.material.roughness, c.gltf.material.metallic,
                  100.0 * c.gltf.residual.l2_relative, c.gltf.residual.lightness,
                  i + 1 < conversions.size() ? "," : "");
    summary += text;
  }
  if (!result.notices.empty()) {
    summary += " (" + std::to_string(result.notices.size()) + " thing(s) not carried)";
  }
  return summary;
}

}  // namespace gloss

#include "editor/model/view/ab_compare.h"

#include "editor/model/document/document.h"

namespace gloss {

AbSides ab_sides(AbSource source, bool raster, ShadingFrequency shading) {
  switch (source) {
    case AbSource::models:
    case AbSource::snapshot:
      return {{raster, shading}, {raster, shading}};
    case AbSource::cpu_gl:
      return {{false, shading}, {true, shading}};
    case AbSource::pixel_vertex:
      return {{true, ShadingFrequency::pixel}, {true, ShadingFrequency::vertex}};
    case AbSource::reference:
      return {{false, shading, false}, {false, shading, true}};
  }
  return {};
}

AbScenes ab_scenes(const Scene& document, AbSource source, const Snapshot* snapshot,
                   bool keep_highlight_size) {
  switch (source) {
    case AbSource::snapshot:
      return {snapshot != nullptr ? snapshot->scene : document, document};
    case AbSource::cpu_gl: {
      AbScenes pair{document, document};
      pair.a.render.spp = 1;
      return pair;
    }
    case AbSource::pixel_vertex:
      return {document, document};
    case AbSource::reference: {
      AbScenes pair{document, document};
      pair.a.render.spp = pair.b.render.spp = 1;
      return pair;
    }
    case AbSource::models:
      break;
  }
  return {with_model(document, ShadingModel::phong, keep_highlight_size),
          with_model(document, ShadingModel::blinn_phong, keep_highlight_size)};
}

std::string ab_label_a(AbSource source, const Snapshot* snapshot) {
  switch (source) {
    case AbSource::snapshot:
      return "A: " + (snapshot != nullptr ? snapshot->label : std::string("no snapshot"));
    case AbSource::cpu_gl:
      return "A: ray traced, 1 spp";
    case AbSource::pixel_vertex:
      return "A: raster, per pixel";
    case AbSource::reference:
      return "A: material, 1 spp";
    case AbSource::models:
      break;
  }
  return "A: Phong";
}

std::string ab_label_b(AbSource source, bool keep_highlight_size, ShadingFrequency shading) {
  switch (source) {
    case AbSource::snapshot:
      return "B: live";
    case AbSource::cpu_gl:
      return shading == ShadingFrequency::pixel ? "B: raster (GLSL), per pixel"
                                                : "B: raster (GLSL), per vertex";
    case AbSource::pixel_vertex:
      return "B: raster, per vertex (Gouraud)";
    case AbSource::reference:
      return "B: physical reference (GGX), 1 spp";
    case AbSource::models:
      break;
  }
  return keep_highlight_size ? "B: Blinn-Phong (exponents x4)" : "B: Blinn-Phong (same exponents)";
}

}  // namespace gloss

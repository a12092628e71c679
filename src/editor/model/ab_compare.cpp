#include "editor/model/ab_compare.h"

#include "editor/model/document.h"

namespace gloss {

AbScenes ab_scenes(const Scene& document, AbSource source, const Snapshot* snapshot,
                   bool keep_highlight_size) {
  if (source == AbSource::snapshot) {
    return {snapshot != nullptr ? snapshot->scene : document, document};
  }
  return {with_model(document, ShadingModel::phong, keep_highlight_size),
          with_model(document, ShadingModel::blinn_phong, keep_highlight_size)};
}

std::string ab_label_a(AbSource source, const Snapshot* snapshot) {
  if (source == AbSource::snapshot) {
    return "A: " + (snapshot != nullptr ? snapshot->label : std::string("no snapshot"));
  }
  return "A: Phong";
}

std::string ab_label_b(AbSource source, bool keep_highlight_size) {
  if (source == AbSource::snapshot) return "B: live";
  return keep_highlight_size ? "B: Blinn-Phong (exponents x4)" : "B: Blinn-Phong (same exponents)";
}

}  // namespace gloss

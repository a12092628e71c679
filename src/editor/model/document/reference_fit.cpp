#include "editor/model/document/reference_fit.h"

#include <cstdio>

#include "physical/phong_fit.h"

namespace gloss {

ReferenceFit fit_to_reference(const Scene& scene, int object, ShadingModel model,
                              LobeMetric metric) {
  if (object < 0 || object >= static_cast<int>(scene.objects.size())) {
    throw CommandError("no object " + std::to_string(object));
  }
  const int index = scene.objects[static_cast<std::size_t>(object)].material;
  if (index < 0 || index >= static_cast<int>(scene.materials.size())) {
    throw CommandError("object " + std::to_string(object) + " has no valid material");
  }
  const Material& material = scene.materials[static_cast<std::size_t>(index)];
  if (!material.reference) {
    throw CommandError("object " + std::to_string(object) +
                       "'s material has no physical reference to fit (give it one first)");
  }
  FitOptions options;
  options.model = model;
  options.metric = metric;
  options.energy_normalize = scene.render.energy_normalize;
  ReferenceFit out;
  out.reference = *material.reference;
  out.report = fit_reference_report(*material.reference, options);
  out.before = phong_residual(phong_lobe(material, model, options.energy_normalize),
                              *material.reference, options.grid);
  out.command.object = object;
  out.command.material = apply_fit(material, out.report.fit);
  if (scene.render.model != model) out.command.model = model;
  out.command.label = std::string("fit ") +
                      (model == ShadingModel::phong ? "Phong" : "Blinn-Phong") + " to " +
                      reference_text(*material.reference);
  return out;
}

std::string residual_summary(const LobeResidual& r) {
  char text[128];
  std::snprintf(text, sizeof text, "l2 %.4g (%.3f of the reference), lightness %.3g L*", r.l2,
                r.l2_relative, r.lightness);
  return text;
}

}  // namespace gloss

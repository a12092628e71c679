#pragma once
// The editor's fit (the Reference panel's Fit Phong / Fit Blinn-Phong and the `fit` script line):
// the material of one object fitted to its physical reference (physical/phong_fit.h) for the
// document's energy normalisation switch, as one undoable command and the report it shows.
#include "analysis/lobe/fit_report.h"
#include "editor/model/document/command.h"
#include "scene/scene.h"

namespace gloss {

struct ReferenceFit {
  ApplyFit command;     // the fitted material, and the model switch when the scene uses the other
  FitReport report;     // constants, residuals, time
  LobeResidual before;  // the material as it was, in the fitted model, against the reference
  PhysicalReference reference;  // what was fitted to
};

// Fits model to the reference of the material object `object` uses, with the scene's
// render.energy_normalize, minimising metric. The material keeps its ka, ke and reference; its
// preset name is cleared. Throws CommandError when the object does not exist or its material
// has no reference. Runs in well under a second (benchmarks/benchmark_fit.cpp); callers that
// must not wait run it on a worker.
ReferenceFit fit_to_reference(const Scene& scene, int object, ShadingModel model,
                              LobeMetric metric = LobeMetric::l2);

// The residual line the panel and the script print: "l2 3.21 (0.503 of the reference), lightness
// 36.9 L*".
std::string residual_summary(const LobeResidual& residual);

}  // namespace gloss

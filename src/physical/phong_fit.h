#pragma once
// The fit of docs/spec/physical-reference.md: the Phong or Blinn-Phong kd, ks and alpha whose
// lobe (physical/lobe_models.h) comes closest to a target lobe in a chosen metric
// (physical/lobe_metrics.h) over pairs of light and view directions (physical/lobe_samples.h).
// ka and ke are not part of it. The target is any sampled lobe: the physical reference, or
// another Phong or Blinn-Phong material (model to model, which measures the 4x exponent rule).
//
// How: a scan of alpha over [0, 1e6] (64 steps even in log(1 + alpha)) with kd and ks solved
// exactly for each alpha in the l2 metric (per channel, non-negative least squares of two
// unknowns), then Levenberg-Marquardt (physical/least_squares.h) over the seven parameters
// (kd, ks, log(1 + alpha)) in the chosen metric from the best of the scan. Deterministic.
#include "physical/lobe_metrics.h"
#include "physical/lobe_models.h"
#include "physical/lobe_samples.h"
#include "scene/material.h"
#include "scene/physical_reference.h"
#include "scene/render_settings.h"

namespace gloss {

// The largest exponent a fit gives: the shininess field's own range.
inline constexpr double kMaxFitExponent = 1e6;

struct FitOptions {
  ShadingModel model = ShadingModel::phong;  // the lobe fitted
  bool energy_normalize = false;             // its specular x (alpha + 2) / 2pi, (alpha + 8) / 8pi
  LobeMetric metric = LobeMetric::l2;        // what is minimised; both are reported
  LobeGrid grid;                             // grid.width is set from the target
};

struct PhongFit {
  PhongLobe lobe;         // the fitted kd, ks, alpha (and the model and switch they are for)
  LobeResidual residual;  // against the target, in both metrics
  int iterations = 0;     // Levenberg-Marquardt iterations
  int evaluations = 0;    // lobe evaluations, the scan's included
  int pairs = 0;          // light-view pairs integrated over
};

// To a lobe sampled over samples (any target). Throws std::invalid_argument when the samples
// hold fewer than 64 pairs (a max_angle_deg of a few degrees) or target is not sampled on them.
PhongFit fit_phong_lobe(const LobeSamples& samples, const SampledLobe& target,
                        const FitOptions& options);

// To a material's physical reference (grid width from its GGX a).
PhongFit fit_phong_to_reference(const PhysicalReference& reference, FitOptions options);

// To another Phong or Blinn-Phong lobe (grid width from its exponent).
PhongFit fit_phong_to_phong(const PhongLobe& source, FitOptions options);

// How far a given Phong or Blinn-Phong lobe is from a reference (a preset against its measured
// metal), over the grid the reference's fit uses.
LobeResidual phong_residual(const PhongLobe& lobe, const PhysicalReference& reference,
                            const LobeGrid& grid = {});

// base with the fit's kd, ks and alpha (as floats); ka, ke and the reference kept, the preset
// name cleared (the constants are no longer the table's).
Material apply_fit(const Material& base, const PhongFit& fit);

}  // namespace gloss

#pragma once
// One answer of the fit (physical/phong_fit.h) as gloss-cli fit and the editor's Reference panel
// report it: what was fitted to what, the constants, the residuals in both metrics, how long it
// took, and beside them what a user compares them with: for a reference, the measured F0 with
// its source and what an environment light would want (physical/environment_match.h); for a
// Phong material moved to the other model, the editor's 4x exponent rule.
#include <optional>
#include <string>
#include <vector>

#include "base/text/number_text.h"
#include "physical/environment_match.h"
#include "physical/phong_fit.h"
#include "scene/physical_reference.h"

namespace gloss {

struct FitReport {
  FitOptions options;
  PhongFit fit;
  double milliseconds = 0.0;  // the fit alone (pairs, target lobe, scan, minimiser)

  // Fitted to a physical reference:
  std::optional<PhysicalReference> reference;
  std::optional<EnvironmentMatch> environment;
  // ... with a preset named beside it: that preset's own lobe against the reference.
  std::string preset;
  std::optional<Material> preset_material;
  std::optional<LobeResidual> preset_residual;

  // Fitted to another Phong or Blinn-Phong lobe (model to model):
  std::optional<PhongLobe> source;
  std::optional<PhongLobe> rule;  // the 4x rule's lobe: kd, ks kept, alpha x4 (or / 4)
  LobeResidual rule_residual;     // its residual against the source
};

// Fits options.model to the reference and times it; preset (may be null) is set beside it.
FitReport fit_reference_report(const PhysicalReference& reference, const FitOptions& options,
                               const Material* preset = nullptr,
                               const std::string& preset_name = {});
// Fits options.model to source (model to model), with the 4x rule beside it.
FitReport fit_model_report(const PhongLobe& source, const FitOptions& options,
                           const std::string& source_name = {});

// The report as text lines (gloss-cli fit's output; the panel shows some of them).
std::vector<std::string> fit_report_lines(const FitReport& report);
// ... and as a JSON document (gloss-cli fit --json).
std::string fit_report_json(const FitReport& report);

// The lobes in the plane of incidence for a light at elevation_deg (analysis/lobe/brdf_lobe.h's
// frame and units), 181 outgoing angles from -90 to 90 degrees, as CSV with a header:
// theta_deg, then the luminance of the reference (when fitted to one), of the source (model to
// model), of the fitted lobe, of the preset (when named), each diffuse plus specular.
std::string fit_lobe_csv(const FitReport& report, double elevation_deg);

// A colour as the report writes it, with digits significant digits (numbers: number_text).
std::string rgb_text(const glm::dvec3& c, int digits = 6);

// The exponent of the editor's keep-highlight-size rule (Blinn-Phong = 4 x Phong), unclamped.
double four_times_rule(double alpha, ShadingModel from, ShadingModel to);

}  // namespace gloss

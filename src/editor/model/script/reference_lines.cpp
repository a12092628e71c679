// The physical reference's script lines (issue 23; docs/editor.md, "Scripted mode").
#include <string>

#include "editor/model/script/script_tokens.h"
#include "scene/fields/fields.h"

namespace gloss {

// `reference METAL ROUGHNESS`, `reference dielectric R G B ROUGHNESS`, `reference none` and
// `fit phong|blinn-phong [l2|lightness]` (issue 23). Ranges are the reference table's, checked
// here so a bad line fails before the script runs.
ScriptAction parse_reference(Tokens& t) {
  const std::string& kind = t.word("reference (a metal, dielectric or none)");
  if (kind == "none") return ReferenceAction{};
  PhysicalReference r;
  if (!parse_reference_kind(kind.c_str(), r.kind)) {
    std::string names;
    for (int i = 0; i < kReferenceKinds; ++i) {
      names += std::string(names.empty() ? "" : ", ") + to_string(static_cast<ReferenceKind>(i));
    }
    throw std::runtime_error("reference must be one of " + names + " or none, got '" + kind + "'");
  }
  if (!is_metal(r.kind)) r.base = t.vec3("base colour R G B");
  r.roughness = t.number("roughness");
  for (const Field<PhysicalReference>& f : reference_fields()) {
    const FieldProblem problem = field_problem(f, f.get(r));
    if (!problem.message.empty()) {
      throw std::runtime_error(std::string("reference ") + f.key + " " + problem.message);
    }
  }
  return ReferenceAction{r};
}

ScriptAction parse_fit(Tokens& t) {
  FitAction a;
  const std::string& model = t.word("model to fit");
  if (!parse_shading_model(model, a.model)) {
    throw std::runtime_error("fit must be phong or blinn-phong, got '" + model + "'");
  }
  if (!t.done()) {
    const std::string& metric = t.word("metric");
    if (!parse_lobe_metric(metric.c_str(), a.metric)) {
      throw std::runtime_error("the fit's metric must be l2 or lightness, got '" + metric + "'");
    }
  }
  return a;
}

}  // namespace gloss

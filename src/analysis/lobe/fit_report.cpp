#include "analysis/lobe/fit_report.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "analysis/lobe/brdf_lobe.h"
#include "physical/measured_metals.h"

namespace gloss {

namespace {

std::string rgb(const glm::dvec3& c) {
  return rgb_text(c);
}

std::string number(const char* format, double x) {
  char text[64];
  std::snprintf(text, sizeof text, format, x);
  return text;
}

std::string residual_text(const LobeResidual& r) {
  return "l2 " + number("%.4g", r.l2) + " (relative " + number("%.4f", r.l2_relative) +
         "), lightness " + number("%.4g", r.lightness) + " L*";
}

std::string lobe_name(const PhongLobe& lobe) {
  return std::string(to_string(lobe.model)) + " kd " + rgb(lobe.kd) + " ks " + rgb(lobe.ks) +
         " alpha " + number("%.6g", lobe.alpha);
}

// A float as the double its shortest decimal text reads as (0.2f as 0.2, not 0.200000003).
double shortest(float f) {
  char text[32];
  for (int digits = 1; digits <= 9; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, static_cast<double>(f));
    if (std::strtof(text, nullptr) == f) break;
  }
  return std::strtod(text, nullptr);
}

nlohmann::json json_rgb(const glm::dvec3& c) {
  return nlohmann::json::array({c.x, c.y, c.z});
}

nlohmann::json json_residual(const LobeResidual& r) {
  return {{"l2", r.l2}, {"l2_relative", r.l2_relative}, {"lightness", r.lightness}};
}

nlohmann::json json_lobe(const PhongLobe& lobe) {
  return {{"model", to_string(lobe.model)},
          {"energy_normalize", lobe.energy_normalize},
          {"diffuse", json_rgb(lobe.kd)},
          {"specular", json_rgb(lobe.ks)},
          {"shininess", lobe.alpha}};
}

double elapsed_ms(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

std::string rgb_text(const glm::dvec3& c, int digits) {
  char text[96];
  std::snprintf(text, sizeof text, "%.*g %.*g %.*g", digits, c.x, digits, c.y, digits, c.z);
  return text;
}

double four_times_rule(double alpha, ShadingModel from, ShadingModel to) {
  if (from == to) return alpha;
  return to == ShadingModel::blinn_phong ? 4.0 * alpha : alpha / 4.0;
}

FitReport fit_reference_report(const PhysicalReference& reference, const FitOptions& options,
                               const Material* preset, const std::string& preset_name) {
  FitReport report;
  report.options = options;
  report.reference = reference;
  const auto start = std::chrono::steady_clock::now();
  report.fit = fit_phong_to_reference(reference, options);
  report.milliseconds = elapsed_ms(start);
  report.environment = match_environment(make_reference_brdf(reference), options.model);
  if (preset != nullptr) {
    report.preset = preset_name;
    report.preset_material = *preset;
    report.preset_residual = phong_residual(
        phong_lobe(*preset, options.model, options.energy_normalize), reference, options.grid);
  }
  return report;
}

FitReport fit_model_report(const PhongLobe& source, const FitOptions& options,
                           const std::string& source_name) {
  FitReport report;
  report.options = options;
  report.source = source;
  report.preset = source_name;
  const auto start = std::chrono::steady_clock::now();
  report.fit = fit_phong_to_phong(source, options);
  report.milliseconds = elapsed_ms(start);
  PhongLobe rule = source;
  rule.model = options.model;
  rule.energy_normalize = options.energy_normalize;
  rule.alpha = four_times_rule(source.alpha, source.model, options.model);
  report.rule = rule;
  // Over the pairs the fit used (the grid follows the source's exponent).
  LobeGrid grid = options.grid;
  grid.width = lobe_width_for_exponent(source.model == ShadingModel::phong ? 4.0 * source.alpha
                                                                           : source.alpha);
  const LobeSamples samples = make_lobe_samples(grid);
  report.rule_residual =
      lobe_residual(samples, sample_phong(source, samples), sample_phong(rule, samples));
  return report;
}

std::vector<std::string> fit_report_lines(const FitReport& r) {
  std::vector<std::string> lines;
  const FitOptions& o = r.options;
  if (r.reference) {
    const PhysicalReference& ref = *r.reference;
    std::string what = std::string("fit ") + to_string(o.model) + " to " + to_string(ref.kind);
    if (!is_metal(ref.kind)) what += " base " + rgb(glm::dvec3(ref.base));
    what += " roughness " + number("%.6g", ref.roughness) + " (GGX a " +
            number("%.6g", double(ref.roughness) * ref.roughness) + ")";
    lines.push_back(what);
    if (is_metal(ref.kind)) {
      lines.push_back(std::string("  F0 ") + rgb(reference_f0(ref.kind)) + " (linear sRGB, " +
                      kMeasuredF0Source + ")");
    } else {
      lines.push_back("  F0 0.04 (dielectric, index 1.5) under the base colour");
    }
  } else if (r.source) {
    lines.push_back(std::string("fit ") + to_string(o.model) + " to " +
                    (r.preset.empty() ? std::string() : r.preset + ": ") + lobe_name(*r.source));
  }
  lines.push_back(std::string("  under a point light, energy normalisation ") +
                  (o.energy_normalize ? "on" : "off") + "; minimising " + to_string(o.metric) +
                  " over " + std::to_string(r.fit.pairs) + " light-view pairs within " +
                  number("%g", o.grid.max_angle_deg) + " degrees of the normal");
  lines.push_back("diffuse " + rgb(r.fit.lobe.kd));
  lines.push_back("specular " + rgb(r.fit.lobe.ks));
  lines.push_back("shininess " + number("%.6g", r.fit.lobe.alpha));
  lines.push_back("residual " + residual_text(r.fit.residual));
  lines.push_back("time " + number("%.1f", r.milliseconds) + " ms (" +
                  std::to_string(r.fit.iterations) + " iterations, " +
                  std::to_string(r.fit.evaluations) + " lobe evaluations)");
  if (r.preset_residual) {
    lines.push_back("preset " + r.preset + " as it is: residual " +
                    residual_text(*r.preset_residual));
  }
  if (r.rule) {
    lines.push_back("4x rule (" + lobe_name(*r.rule) + "): residual " +
                    residual_text(r.rule_residual));
  }
  if (r.environment) {
    const EnvironmentMatch& e = *r.environment;
    lines.push_back("environment: ks " + rgb(e.albedo_mean) + " (mean albedo; head-on " +
                    rgb(e.albedo_normal) + ", at 80 degrees " + rgb(e.albedo_grazing) +
                    "), shininess " + number("%.6g", e.alpha) + " (lobe residual " +
                    number("%.3f", e.residual) + ")");
  }
  return lines;
}

std::string fit_lobe_csv(const FitReport& r, double elevation_deg) {
  // One curve: a material's diffuse plus the lobe of the given model, or its reference.
  struct Curve {
    std::string name;
    Material material;
    ShadingModel model;
    bool energy;
    bool reference;
  };
  std::vector<Curve> curves;
  auto as_material = [](const PhongLobe& lobe) {
    Material m;
    m.diffuse = glm::vec3(lobe.kd);
    m.specular = glm::vec3(lobe.ks);
    m.shininess = static_cast<float>(lobe.alpha);
    return m;
  };
  if (r.reference) {
    Material m;
    m.reference = r.reference;
    curves.push_back({"reference", m, r.options.model, false, true});
  }
  if (r.source) {
    curves.push_back(
        {"source", as_material(*r.source), r.source->model, r.source->energy_normalize, false});
  }
  curves.push_back(
      {"fit", as_material(r.fit.lobe), r.fit.lobe.model, r.fit.lobe.energy_normalize, false});
  if (r.preset_material) {
    curves.push_back(
        {"preset", *r.preset_material, r.options.model, r.options.energy_normalize, false});
  }
  if (r.rule) {
    curves.push_back(
        {"rule", as_material(*r.rule), r.rule->model, r.rule->energy_normalize, false});
  }
  std::string text = "theta_deg";
  for (const Curve& c : curves) text += "," + c.name;
  text += "\n";
  for (int i = 0; i <= 180; ++i) {
    const double theta = -90.0 + i;
    text += number("%g", theta);
    for (const Curve& c : curves) {
      LobeParams params;
      params.elevation_deg = elevation_deg;
      params.phong_alpha = params.blinn_alpha = c.material.shininess;
      params.energy_normalize = c.energy;
      const LobeSample s = lobe_sample(c.material, params, theta);
      const glm::dvec3 value = c.reference                      ? s.reference
                               : c.model == ShadingModel::phong ? s.diffuse + s.phong
                                                                : s.diffuse + s.blinn;
      text += "," + number("%.9g", luminance(value));
    }
    text += "\n";
  }
  return text;
}

std::string fit_report_json(const FitReport& r) {
  nlohmann::ordered_json j;
  j["model"] = to_string(r.options.model);
  j["energy_normalize"] = r.options.energy_normalize;
  j["metric"] = to_string(r.options.metric);
  j["max_angle_deg"] = r.options.grid.max_angle_deg;
  if (r.reference) {
    const PhysicalReference& ref = *r.reference;
    nlohmann::ordered_json reference;
    reference["kind"] = to_string(ref.kind);
    if (!is_metal(ref.kind)) {
      reference["base"] = {shortest(ref.base.x), shortest(ref.base.y), shortest(ref.base.z)};
    }
    reference["roughness"] = shortest(ref.roughness);
    reference["f0"] = json_rgb(reference_f0(ref.kind));
    reference["f0_source"] = is_metal(ref.kind) ? kMeasuredF0Source : "dielectric, index 1.5";
    j["reference"] = reference;
  }
  if (r.source) j["source"] = json_lobe(*r.source);
  j["diffuse"] = json_rgb(r.fit.lobe.kd);
  j["specular"] = json_rgb(r.fit.lobe.ks);
  j["shininess"] = r.fit.lobe.alpha;
  j["residual"] = json_residual(r.fit.residual);
  j["pairs"] = r.fit.pairs;
  j["iterations"] = r.fit.iterations;
  j["evaluations"] = r.fit.evaluations;
  j["milliseconds"] = r.milliseconds;
  if (r.preset_residual) {
    j["preset"] = r.preset;
    j["preset_residual"] = json_residual(*r.preset_residual);
  }
  if (r.rule) {
    j["rule"] = json_lobe(*r.rule);
    j["rule_residual"] = json_residual(r.rule_residual);
  }
  if (r.environment) {
    const EnvironmentMatch& e = *r.environment;
    j["environment"] = {{"ks", json_rgb(e.albedo_mean)},
                        {"albedo_normal", json_rgb(e.albedo_normal)},
                        {"albedo_80deg", json_rgb(e.albedo_grazing)},
                        {"shininess", e.alpha},
                        {"lobe_residual", e.residual}};
  }
  return j.dump(2) + "\n";
}

}  // namespace gloss

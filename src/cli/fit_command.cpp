// gloss-cli fit --reference gold|silver|aluminium|copper|chromium|brass|dielectric
//               [--base R,G,B] --roughness R [--model phong|blinn-phong] [--energy-normalize]
//               [--metric l2|lightness] [--max-angle DEG] [--preset NAME] [--json FILE]
//               [--lobe-csv FILE [--elevation DEG]] [--add-to FILE --name NAME]
// gloss-cli fit --preset NAME --model phong|blinn-phong [--from phong|blinn-phong]
//               [--source-shininess A] ...
// The Phong or Blinn-Phong constants closest to a physical reference (docs/phong-vs-reference.md),
// or to a preset shown in the other model (model to model, beside the 4x exponent rule).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "analysis/lobe/fit_report.h"
#include "base/atomic_file.h"
#include "base/error.h"
#include "base/text/number_text.h"
#include "base/text/text_distance.h"
#include "cli/commands.h"
#include "io/material/material_io.h"
#include "io/material/preset_table.h"

namespace gloss {

namespace {

// Errors name the subcommand as their "file" and the option as their field.
const char* const kWhere = "fit";

struct FitArgs {
  std::string reference, base, model = "phong", from, metric = "l2", preset, json, add_to, name;
  std::string lobe_csv;
  double roughness = 0.0, max_angle = 80.0, elevation = 45.0, source_shininess = 0.0;
  bool energy_normalize = false;
  CLI::Option *roughness_option = nullptr, *base_option = nullptr, *from_option = nullptr;
  CLI::Option* source_shininess_option = nullptr;
};

std::vector<std::string> reference_names() {
  std::vector<std::string> names;
  for (int i = 0; i < kReferenceKinds; ++i) names.emplace_back(to_string(ReferenceKind(i)));
  return names;
}

[[noreturn]] void fail(const std::string& option, const std::string& message) {
  throw InputError(kWhere, message, 0, 0, option);
}

std::string did_you_mean(const std::string& word, const std::vector<std::string>& names) {
  return " (did you mean '" + nearest_words(word, names, 1).front() + "'?)";
}

ShadingModel model_of(const std::string& option, const std::string& name) {
  ShadingModel model;
  if (!parse_shading_model(name, model)) {
    fail(option,
         "unknown shading model '" + name + "'" + did_you_mean(name, {"phong", "blinn-phong"}));
  }
  return model;
}

// "R,G,B", each in [0, 1].
glm::vec3 base_colour(const std::string& text) {
  std::vector<float> values;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string part = text.substr(start, comma == std::string::npos ? comma : comma - start);
    char* end = nullptr;
    const double x = std::strtod(part.c_str(), &end);
    if (part.empty() || *end != '\0' || !(x >= 0.0 && x <= 1.0)) {
      fail("--base", "expected R,G,B with each from 0 to 1, got '" + text + "'");
    }
    values.push_back(static_cast<float>(x));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (values.size() != 3) fail("--base", "expected R,G,B (three numbers), got '" + text + "'");
  return {values[0], values[1], values[2]};
}

const Preset& preset_of(const std::string& name) {
  const Preset* preset = find_preset(name);
  if (preset == nullptr) {
    std::string nearest;
    for (const std::string& n : nearest_preset_names(name))
      nearest += (nearest.empty() ? "" : ", ") + n;
    fail("--preset", "unknown preset '" + name + "' (nearest: " + nearest + ")");
  }
  return *preset;
}

FitOptions options_of(const FitArgs& args) {
  FitOptions options;
  options.model = model_of("--model", args.model);
  options.energy_normalize = args.energy_normalize;
  if (!parse_lobe_metric(args.metric.c_str(), options.metric)) {
    fail("--metric",
         "unknown metric '" + args.metric + "'" + did_you_mean(args.metric, {"l2", "lightness"}));
  }
  // Below 10 degrees too few light-view pairs are left to fit three parameters per channel.
  if (!(args.max_angle >= 10.0 && args.max_angle <= 90.0)) {
    fail("--max-angle", "must be from 10 to 90 degrees, got " + number_text(args.max_angle));
  }
  options.grid.max_angle_deg = args.max_angle;
  return options;
}

PhysicalReference reference_of(const FitArgs& args) {
  PhysicalReference reference;
  if (!parse_reference_kind(args.reference.c_str(), reference.kind)) {
    fail("--reference", "unknown reference '" + args.reference + "'" +
                            did_you_mean(args.reference, reference_names()));
  }
  if (!*args.roughness_option) fail("--roughness", "missing: give the roughness, 0 < R <= 1");
  if (!(args.roughness > 0.0 && args.roughness <= 1.0)) {
    fail("--roughness", "must be > 0 and <= 1, got " + number_text(args.roughness));
  }
  reference.roughness = static_cast<float>(args.roughness);
  if (*args.base_option) {
    if (is_metal(reference.kind)) {
      fail("--base", std::string("only a dielectric has a base colour (") +
                         to_string(reference.kind) + " is a measured metal)");
    }
    reference.base = base_colour(args.base);
  }
  return reference;
}

// The fitted material as the materials file keeps it: kd, ks, alpha from the fit, the reference
// block, and ka = the reference's mean albedo (what a uniform ambient light of radiance 1
// reflects, physical/environment_match.h); with --preset, that preset's ka and ke instead.
Material fitted_material(const FitReport& report, const Material* preset) {
  Material base;
  if (preset != nullptr) {
    base = *preset;
  } else {
    base.ambient = glm::vec3(report.environment->albedo_mean);
    base.emission = glm::vec3(0.0f);
  }
  Material m = apply_fit(base, report.fit);
  m.reference = report.reference;
  return m;
}

void add_to_materials_file(const std::string& path, const std::string& name, const Material& m) {
  std::vector<NamedMaterial> materials;
  if (std::ifstream(path).good()) materials = load_materials_json(path);
  bool replaced = false;
  for (NamedMaterial& entry : materials) {
    if (entry.first == name) {
      entry.second = m;
      replaced = true;
    }
  }
  if (!replaced) materials.emplace_back(name, m);
  save_materials_json(path, materials);
}

void run_fit(const FitArgs& args) {
  const FitOptions options = options_of(args);
  if (!args.add_to.empty() && args.name.empty()) fail("--name", "--add-to needs a --name");
  if (!(args.elevation >= 0.0 && args.elevation <= 90.0)) {
    fail("--elevation", "must be from 0 to 90 degrees, got " + number_text(args.elevation));
  }
  if (args.reference.empty() && args.preset.empty()) {
    fail("--reference",
         "give --reference KIND with --roughness R, or --preset NAME to fit one "
         "model's lobe to the other's");
  }
  FitReport report;
  const Preset* preset = args.preset.empty() ? nullptr : &preset_of(args.preset);
  if (!args.reference.empty()) {
    if (*args.from_option) fail("--from", "--from is for fitting a preset, not a reference");
    if (*args.source_shininess_option) {
      fail("--source-shininess", "--source-shininess is for fitting a preset, not a reference");
    }
    report = fit_reference_report(reference_of(args), options,
                                  preset != nullptr ? &preset->material : nullptr, args.preset);
  } else {
    if (!args.add_to.empty()) fail("--add-to", "only a fit to a reference is added to a file");
    const ShadingModel from = *args.from_option                      ? model_of("--from", args.from)
                              : options.model == ShadingModel::phong ? ShadingModel::blinn_phong
                                                                     : ShadingModel::phong;
    Material source = preset->material;
    if (*args.source_shininess_option) {
      if (!(args.source_shininess >= 0.0 && args.source_shininess <= kMaxFitExponent)) {
        fail("--source-shininess",
             "must be from 0 to 1e6, got " + number_text(args.source_shininess));
      }
      source.shininess = static_cast<float>(args.source_shininess);
    }
    report = fit_model_report(phong_lobe(source, from, options.energy_normalize), options,
                              "preset " + args.preset);
  }
  for (const std::string& line : fit_report_lines(report)) std::cout << line << "\n";
  if (!args.json.empty()) {
    write_text_atomically(args.json, fit_report_json(report));
    std::cout << "wrote " << args.json << "\n";
  }
  if (!args.lobe_csv.empty()) {
    write_text_atomically(args.lobe_csv, fit_lobe_csv(report, args.elevation));
    std::cout << "wrote " << args.lobe_csv << "\n";
  }
  if (!args.add_to.empty()) {
    add_to_materials_file(args.add_to, args.name, fitted_material(report, nullptr));
    std::cout << "added " << args.name << " to " << args.add_to << "\n";
  }
}

}  // namespace

void add_fit_command(CLI::App& app) {
  auto args = std::make_shared<FitArgs>();
  CLI::App* cmd = app.add_subcommand(
      "fit",
      "The Phong / Blinn-Phong constants closest to a measured metal or a dielectric "
      "(GGX), or to a preset in the other model");
  cmd->add_option("--reference", args->reference,
                  "gold, silver, aluminium, copper, chromium, brass (F0: Real-Time Rendering, "
                  "4th ed., Table 9.2) or dielectric");
  args->base_option =
      cmd->add_option("--base", args->base, "Dielectric base colour R,G,B (linear, 0..1)");
  args->roughness_option =
      cmd->add_option("--roughness", args->roughness, "Perceptual roughness, 0 < R <= 1");
  cmd->add_option("--model", args->model, "The model fitted: phong (default) or blinn-phong");
  cmd->add_flag("--energy-normalize", args->energy_normalize,
                "Fit the energy-normalised lobe (ks x (alpha + 2) / 2pi, (alpha + 8) / 8pi)");
  cmd->add_option("--metric", args->metric,
                  "What is minimised: l2 (Ngan et al. 2005, default) or lightness (CIE L*)");
  cmd->add_option("--max-angle", args->max_angle,
                  "Light and view within this many degrees of the normal, 10..90 (default 80)");
  cmd->add_option("--preset", args->preset,
                  "With --reference: also the preset's own error; alone: fit --model to the "
                  "preset shown in the other model (--from), beside the 4x exponent rule");
  args->from_option =
      cmd->add_option("--from", args->from, "The preset's model (default: the other one)");
  args->source_shininess_option = cmd->add_option("--source-shininess", args->source_shininess,
                                                  "The preset's exponent replaced by this one");
  cmd->add_option("--json", args->json, "Also write the result as JSON to FILE");
  cmd->add_option("--lobe-csv", args->lobe_csv,
                  "Also write the lobes in the plane of incidence (luminance per outgoing angle) "
                  "as CSV to FILE");
  cmd->add_option("--elevation", args->elevation,
                  "The light's elevation for --lobe-csv, degrees (default 45)");
  cmd->add_option("--add-to", args->add_to,
                  "Add (or replace) the fitted material in the materials file FILE");
  cmd->add_option("--name", args->name, "The material's name in --add-to's file");
  cmd->callback([args] { run_fit(*args); });
}

}  // namespace gloss

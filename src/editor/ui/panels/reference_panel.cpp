// The Reference panel (issue 23): the selected object's material held against a physical
// reference (docs/spec/physical-reference.md): pick a measured metal or a dielectric with its
// base colour and a roughness, compare it in the A/B view, and fit Phong or Blinn-Phong to it in
// one undoable step. The fit runs on a worker; its result is applied when it arrives, if the
// reference it was made for is still the material's.
#include <chrono>
#include <cstdio>
#include <string>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "editor/model/document/document.h"
#include "editor/ui/panels/field_widgets.h"
#include "editor/ui/panels/panel_state.h"
#include "editor/ui/panels/panel_widgets.h"
#include "editor/ui/panels/panels.h"
#include "editor/ui/parts/commands.h"
#include "editor/ui/parts/selection.h"
#include "physical/measured_metals.h"
#include "physical/phong_fit.h"

namespace gloss {

namespace {

// The kind combo: "none" or one of the reference kinds, each choice a command (a new kind keeps
// the roughness and base colour; a material without a reference gets the last one removed).
void draw_kind(Commands& commands, ReferencePanelState& state, int object,
               const std::optional<PhysicalReference>& current) {
  const char* shown = current ? to_string(current->kind) : "none";
  if (!ImGui::BeginCombo("reference", shown)) return;
  if (ImGui::Selectable("none", !current) && current) {
    state.last_reference = *current;
    commands.execute(SetReference{object, std::nullopt});
  }
  for (int i = 0; i < kReferenceKinds; ++i) {
    const ReferenceKind kind = static_cast<ReferenceKind>(i);
    if (ImGui::Selectable(to_string(kind), current && current->kind == kind) &&
        !(current && current->kind == kind)) {
      PhysicalReference next = current ? *current : state.last_reference;
      next.kind = kind;
      commands.execute(SetReference{object, next});
    }
  }
  ImGui::EndCombo();
}

// Starts a fit of model on a worker, over a copy of the document.
void start_fit(ReferencePanelState& state, const Scene& scene, int object, ShadingModel model) {
  state.job_model = model;
  const LobeMetric metric = state.metric;
  state.job = std::async(std::launch::async, [scene, object, model, metric] {
    ReferenceFit fit = fit_to_reference(scene, object, model, metric);
    glfwPostEmptyEvent();  // wakes the event loop, which applies it
    return fit;
  });
}

// A finished fit: applied in one step when the material still has the reference it was made
// for; its report kept for the panel.
void collect_fit(Commands& commands, ReferencePanelState& state) {
  if (!state.job.valid() ||
      state.job.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
    return;
  }
  try {
    const ReferenceFit fit = state.job.get();
    const Scene& scene = commands.scene();
    const int object = fit.command.object;
    const int material =
        object < static_cast<int>(scene.objects.size()) ? scene.objects[object].material : -1;
    if (material < 0 || !scene.materials[material].reference ||
        *scene.materials[material].reference != fit.reference) {
      commands.info("the reference changed while fitting: press Fit again");
      return;
    }
    commands.execute(fit.command);
    const PhongFit& f = fit.report.fit;
    state.report = {std::string(to_string(f.lobe.model)) +
                        (f.lobe.energy_normalize ? ", normalised" : "") + ", minimising " +
                        to_string(fit.report.options.metric),
                    "kd " + rgb_text(f.lobe.kd, 4),
                    "ks " + rgb_text(f.lobe.ks, 4),
                    "alpha " + number_text(f.lobe.alpha, 4),
                    "residual now: " + residual_summary(f.residual),
                    "before the fit: " + residual_summary(fit.before)};
    char time[64];
    std::snprintf(time, sizeof time, "%.0f ms, %d light-view pairs", fit.report.milliseconds,
                  f.pairs);
    state.report.emplace_back(time);
    if (fit.command.model) {
      state.report.push_back(std::string("the scene now renders ") + to_string(*fit.command.model));
    }
  } catch (const std::exception& e) {
    commands.error(std::string("fit: ") + e.what());
  }
}

// Keeps state.residual current for the selected material: a new computation when what it
// depends on changed, taken in when it is done.
void refresh_residual(ReferencePanelState& state, const Scene& scene, const Material& material) {
  if (state.residual_job.valid() &&
      state.residual_job.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    state.residual = state.residual_job.get();
  }
  if (!material.reference) {
    state.residual_key.clear();
    state.residual.reset();
    return;
  }
  const PhongLobe lobe = phong_lobe(material, scene.render.model, scene.render.energy_normalize);
  const PhysicalReference reference = *material.reference;
  char key[256];
  std::snprintf(key, sizeof key, "%a %a %a %a %a %a %a %d %d %d %a %a %a %a", lobe.kd.x, lobe.kd.y,
                lobe.kd.z, lobe.ks.x, lobe.ks.y, lobe.ks.z, lobe.alpha,
                static_cast<int>(lobe.model), lobe.energy_normalize ? 1 : 0,
                static_cast<int>(reference.kind), static_cast<double>(reference.base.x),
                static_cast<double>(reference.base.y), static_cast<double>(reference.base.z),
                static_cast<double>(reference.roughness));
  if (key == state.residual_key || state.residual_job.valid()) return;  // current, or running
  if (!state.residual_key.empty()) state.residual.reset();              // what it showed is stale
  state.residual_key = key;
  state.residual_job =
      std::async(std::launch::async, [lobe, reference] { return phong_residual(lobe, reference); });
}

}  // namespace

void draw_reference_panel(Commands& commands, Selection& selection, ViewSettings& view,
                          ReferencePanelState& state, ImVec2 pos, ImVec2 size) {
  collect_fit(commands, state);
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
  if (!ImGui::Begin("Reference", nullptr, flags)) {
    ImGui::End();
    return;
  }
  const Scene& scene = commands.scene();
  if (scene.objects.empty()) {
    ImGui::TextWrapped("No object to compare.");
    ImGui::End();
    return;
  }
  const int object = std::clamp(selection.object, 0, static_cast<int>(scene.objects.size()) - 1);
  const int material_index = scene.objects[object].material;
  // A copy: an executed command replaces the document, and this is read afterwards.
  const std::optional<PhysicalReference> reference = scene.materials[material_index].reference;
  refresh_residual(state, scene, scene.materials[material_index]);
  ImGui::TextDisabled("%s, material '%s'", object_label(scene, object).c_str(),
                      scene.material_names[material_index].c_str());
  ImGui::PushItemWidth(-90.0f);
  draw_kind(commands, state, object, reference);
  if (reference) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    if (is_metal(reference->kind)) {
      ImGui::TextWrapped("F0 %s, measured, linear sRGB (%s)",
                         rgb_text(reference_f0(reference->kind), 3).c_str(), kMeasuredF0Source);
    } else {
      ImGui::TextWrapped("F0 0.04 (index 1.5) over a Lambertian base colour");
    }
    ImGui::PopStyleColor();
    PhysicalReference edited = *reference;
    for (const Field<PhysicalReference>& field : reference_fields()) {
      const std::string key = field.key;
      if (key == "kind" || (key == "base" && is_metal(reference->kind))) continue;
      field_widget(field, edited);
    }
    if (auto command =
            field_command(FieldPart::reference, object, reference_fields(), *reference, edited)) {
      commands.execute(*command);
    }
  }
  ImGui::PopItemWidth();

  section_title("Compare");
  const bool comparing = view.mode == ViewMode::ab && view.ab_source == AbSource::reference;
  if (ImGui::Button(comparing ? "A/B material | reference (shown)" : "A/B material | reference")) {
    view.mode = ViewMode::ab;
    view.ab_source = AbSource::reference;
  }
  ImGui::SameLine();
  if (ImGui::Button("lobe")) view.mode = ViewMode::lobe;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the BRDF lobe view, with the reference's lobe");

  section_title("Fit the material to it");
  int metric = state.metric == LobeMetric::l2 ? 0 : 1;
  ImGui::RadioButton("l2", &metric, 0);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Ngan et al. 2005: the cosine-weighted L2 of the radiance under a unit\n"
        "light, over light and view directions (ruled by the highlight)");
  }
  ImGui::SameLine();
  ImGui::RadioButton("lightness (L*)", &metric, 1);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("the same over CIE L* of each channel: the dim body counts as seen");
  }
  state.metric = metric == 0 ? LobeMetric::l2 : LobeMetric::lightness;
  const bool running = state.job.valid();
  if (!reference || running) ImGui::BeginDisabled();
  if (ImGui::Button("Fit Phong")) start_fit(state, scene, object, ShadingModel::phong);
  ImGui::SameLine();
  if (ImGui::Button("Fit Blinn-Phong")) start_fit(state, scene, object, ShadingModel::blinn_phong);
  if (!reference || running) ImGui::EndDisabled();
  if (running) {
    ImGui::SameLine();
    ImGui::TextUnformatted("fitting...");
  }
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("kd, ks and alpha, under point lights, energy normalisation %s (the scene's)",
                     scene.render.energy_normalize ? "on" : "off");
  ImGui::PopStyleColor();
  if (!reference) {
    ImGui::TextWrapped("Pick a reference to compare with and fit to.");
  } else if (state.residual) {
    ImGui::TextWrapped("the material now (%s): %s", to_string(scene.render.model),
                       residual_summary(*state.residual).c_str());
  } else {
    ImGui::TextDisabled("measuring the material against it...");
  }
  if (!state.report.empty()) section_title("Last fit");
  for (const std::string& line : state.report) ImGui::TextWrapped("%s", line.c_str());
  ImGui::End();
}

}  // namespace gloss

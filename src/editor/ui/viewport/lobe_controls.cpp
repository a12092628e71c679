// The lobe view's controls (lobe_view.cpp draws them above its plots): the light's elevation, the
// normalisation, the radius scale and the 4x rule; which plot and which second material; and the
// exponents each model's curve gets.
#include <algorithm>
#include <cmath>
#include <string>

#include "editor/model/document/document.h"
#include "editor/ui/panels/panel_widgets.h"
#include "editor/ui/viewport/lobe_plots.h"
#include "io/material/preset_table.h"

namespace gloss {

namespace {

const char* energy_label(LobeEnergy energy, bool document) {
  switch (energy) {
    case LobeEnergy::scene:
      return document ? "as the scene (on)" : "as the scene (off)";
    case LobeEnergy::on:
      return "on (view only)";
    case LobeEnergy::off:
      return "off (view only)";
  }
  return "?";
}

}  // namespace

void draw_lobe_controls(ViewSettings& view, bool document_energy) {
  ImGui::PushItemWidth(200.0f);
  ImGui::SliderFloat("light elevation", &view.lobe_elevation_deg, 0.0f, 90.0f,
                     "%.1f\xC2\xB0 above the surface");
  view.lobe_elevation_deg = std::clamp(view.lobe_elevation_deg, 0.0f, 90.0f);
  same_line_if_fits(200.0f + ImGui::GetStyle().ItemInnerSpacing.x +
                    ImGui::CalcTextSize("energy normalisation").x);
  if (ImGui::BeginCombo("energy normalisation", energy_label(view.lobe_energy, document_energy))) {
    for (LobeEnergy e : {LobeEnergy::scene, LobeEnergy::on, LobeEnergy::off}) {
      if (ImGui::Selectable(energy_label(e, document_energy), e == view.lobe_energy)) {
        view.lobe_energy = e;
      }
    }
    ImGui::EndCombo();
  }
  ImGui::PopItemWidth();
  // The row wraps in a narrow viewport instead of running past its edge.
  same_line_if_fits(toggle_width("log radius"));
  ImGui::Checkbox("log radius", &view.lobe_log_radius);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "three decades of luminance, one ring each: a physical reference's\n"
        "bright peak and a classic lobe of ks <= 1 in one plot");
  }
  same_line_if_fits(toggle_width("4x rule"));
  ImGui::Checkbox("4x rule", &view.keep_highlight_size);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "on: the model the scene does not use is drawn with the exponent that keeps\n"
        "the highlight's size (Blinn-Phong 4x Phong's); off: both models with the\n"
        "material's own exponent. The same setting as the Material panel's 'keep\n"
        "highlight size (x4 rule)', which the A/B view's B side follows too");
  }
}

// The second row of controls: which plot, and the second material drawn over the first.
void draw_lobe_plot_controls(ViewSettings& view, const Scene& scene, const Snapshot* snapshot,
                             const std::optional<OverlayMaterial>& overlay) {
  int plot = static_cast<int>(view.lobe_plot);
  ImGui::RadioButton("plane of incidence", &plot, static_cast<int>(LobePlot::plane));
  ImGui::SameLine();
  ImGui::RadioButton("3D", &plot, static_cast<int>(LobePlot::hemisphere));
  ImGui::SameLine();
  ImGui::RadioButton("albedo", &plot, static_cast<int>(LobePlot::albedo));
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "the share of a unit directional light's irradiance the material sends into the\n"
        "hemisphere, against the incidence angle (adaptive quadrature, error stated)");
  }
  view.lobe_plot = static_cast<LobePlot>(plot);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(220.0f);
  const std::string shown = overlay ? overlay->label : "none";
  if (ImGui::BeginCombo("compare with", shown.c_str())) {
    if (ImGui::Selectable("none", view.lobe_overlay == LobeOverlay::none)) {
      view.lobe_overlay = LobeOverlay::none;
    }
    if (ImGui::Selectable(snapshot ? ("snapshot (" + snapshot->label + ")").c_str()
                                   : "snapshot (take one: Ctrl+B)",
                          view.lobe_overlay == LobeOverlay::snapshot,
                          snapshot ? 0 : ImGuiSelectableFlags_Disabled)) {
      view.lobe_overlay = LobeOverlay::snapshot;
    }
    ImGui::Separator();
    for (const std::string& name : scene.material_names) {
      const bool chosen =
          view.lobe_overlay == LobeOverlay::material && view.lobe_overlay_name == name;
      if (ImGui::Selectable(("material '" + name + "'").c_str(), chosen)) {
        view.lobe_overlay = LobeOverlay::material;
        view.lobe_overlay_name = name;
      }
    }
    ImGui::Separator();
    for (const Preset& p : preset_table()) {
      const bool chosen =
          view.lobe_overlay == LobeOverlay::preset && view.lobe_overlay_name == p.name;
      if (ImGui::Selectable(("preset '" + p.name + "'").c_str(), chosen)) {
        view.lobe_overlay = LobeOverlay::preset;
        view.lobe_overlay_name = p.name;
      }
    }
    ImGui::EndCombo();
  }
}

// The exponents each model's curve gets: the scene's model keeps the material's; the other one
// the rescaled exponent when the highlight size is kept (document.h).
AlbedoParams lobe_exponents(const Material& m, const Scene& scene, const ViewSettings& view) {
  const ShadingModel model = scene.render.model;
  AlbedoParams p;
  p.phong_alpha = view.keep_highlight_size
                      ? exponent_for_model(m.shininess, model, ShadingModel::phong)
                      : m.shininess;
  p.blinn_alpha = view.keep_highlight_size
                      ? exponent_for_model(m.shininess, model, ShadingModel::blinn_phong)
                      : m.shininess;
  p.energy_normalize = lobe_energy_normalize(view.lobe_energy, scene.render.energy_normalize);
  return p;
}

void lobe_dashed_line(ImDrawList* list, ImVec2 a, ImVec2 b, ImU32 colour, float thickness) {
  const float dx = b.x - a.x, dy = b.y - a.y;
  const float length = std::hypot(dx, dy);
  const int dashes = std::max(1, static_cast<int>(length / 8.0f));
  for (int i = 0; i < dashes; i += 2) {
    const float s = static_cast<float>(i) / dashes, e = static_cast<float>(i + 1) / dashes;
    list->AddLine(ImVec2(a.x + dx * s, a.y + dy * s), ImVec2(a.x + dx * e, a.y + dy * e), colour,
                  thickness);
  }
}

}  // namespace gloss

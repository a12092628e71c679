// The lobe view's albedo plot: the directional albedo (analysis/lobe/directional_albedo.h) against
// the incidence angle, per model, from the worker's curves (albedo_curves.h), with the
// quadrature's stated error and, at normal incidence, Phong's closed form beside the number.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "analysis/lobe/brdf_lobe.h"
#include "editor/ui/viewport/lobe_plots.h"

namespace gloss {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The plot's axes: incidence 0..90 degrees along x, albedo 0..top along y.
struct AlbedoAxes {
  ImVec2 min{0, 0}, max{0, 0};
  double top = 1.0;
  ImVec2 at(double incidence_deg, double value) const {
    return ImVec2(min.x + static_cast<float>(incidence_deg / 90.0) * (max.x - min.x),
                  max.y - static_cast<float>(value / top) * (max.y - min.y));
  }
};

struct AlbedoLines {
  std::vector<double> diffuse, phong, blinn;  // luminance of the material's albedo
  double error = 0.0;                         // the largest stated error, in luminance
};

AlbedoLines lines_of(const Material& m, const std::vector<AlbedoTerms>& curve) {
  AlbedoLines out;
  // Luminance is linear: the diffuse part is lum(kd) x its share.
  const double kd = luminance(glm::dvec3(m.diffuse)), ks = luminance(glm::dvec3(m.specular));
  for (const AlbedoTerms& t : curve) {
    out.diffuse.push_back(kd * t.diffuse);
    out.phong.push_back(luminance(directional_albedo(m, t, ShadingModel::phong)));
    out.blinn.push_back(luminance(directional_albedo(m, t, ShadingModel::blinn_phong)));
    out.error =
        std::max(out.error, kd * t.diffuse_error + ks * std::max(t.phong_error, t.blinn_error));
  }
  return out;
}

void plot_line(ImDrawList* list, const AlbedoAxes& axes, const std::vector<AlbedoTerms>& curve,
               const std::vector<double>& values, ImU32 colour, float width, bool dashed) {
  for (std::size_t i = 1; i < values.size(); ++i) {
    const ImVec2 a = axes.at(curve[i - 1].incidence_deg, std::min(values[i - 1], axes.top));
    const ImVec2 b = axes.at(curve[i].incidence_deg, std::min(values[i], axes.top));
    if (dashed) {
      lobe_dashed_line(list, a, b, colour, width);
    } else {
      list->AddLine(a, b, colour, width);
    }
  }
}

void draw_axes(ImDrawList* list, const AlbedoAxes& axes) {
  char label[32];
  list->AddRect(axes.min, axes.max, kLobeGrid);
  const double step = axes.top > 2.0 ? 0.5 : axes.top > 0.8 ? 0.2 : 0.1;
  for (double v = step; v < axes.top * 0.999; v += step) {
    const ImVec2 a = axes.at(0.0, v);
    list->AddLine(a, ImVec2(axes.max.x, a.y), kLobeGrid, 1.0f);
    std::snprintf(label, sizeof label, "%.2g", v);
    list->AddText(ImVec2(a.x - ImGui::CalcTextSize(label).x - 6.0f, a.y - 7.0f), kLobeDim, label);
  }
  for (int deg = 0; deg <= 90; deg += 15) {
    const ImVec2 a = axes.at(deg, 0.0);
    list->AddLine(a, ImVec2(a.x, axes.min.y), kLobeGrid, 1.0f);
    std::snprintf(label, sizeof label, "%d\xC2\xB0", deg);
    list->AddText(ImVec2(a.x - ImGui::CalcTextSize(label).x * 0.5f, a.y + 4.0f), kLobeDim, label);
  }
  if (axes.top > 1.0) {  // all of the light: more than this is more than the surface receives
    lobe_dashed_line(list, axes.at(0.0, 1.0), axes.at(90.0, 1.0), kLobeDim, 1.0f);
  }
}

}  // namespace

void draw_lobe_albedo(const LobeSubject& s, AlbedoCurves& curves, AlbedoCurves& overlay_curves,
                      ImVec2 pos, ImVec2 size) {
  ImDrawList* list = ImGui::GetWindowDrawList();
  AlbedoParams asked = s.params;
  asked.tolerance = kAlbedoTolerance;
  const std::vector<AlbedoTerms>* curve = curves.get(asked);
  const std::vector<AlbedoTerms>* overlay = nullptr;
  if (s.overlay) {
    AlbedoParams o = s.overlay_params;
    o.tolerance = kAlbedoTolerance;
    overlay = overlay_curves.get(o);
  }
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float legend_h = 7.0f * line + 10.0f;
  AlbedoAxes axes;
  axes.min = ImVec2(pos.x + 56.0f, pos.y + 14.0f);
  axes.max = ImVec2(pos.x + size.x - 20.0f, pos.y + std::max(size.y - legend_h - 24.0f, 60.0f));
  if (curve == nullptr) {
    list->AddText(ImVec2(pos.x + 16.0f, pos.y + 16.0f), kLobeText,
                  "computing the directional albedo (adaptive quadrature over the hemisphere) ...");
    return;
  }
  const AlbedoLines lines = lines_of(s.material, *curve);
  const AlbedoLines over =
      overlay != nullptr ? lines_of(s.overlay->material, *overlay) : AlbedoLines{};
  double top = 0.0;
  for (const std::vector<double>* v : {&lines.phong, &lines.blinn, &over.phong, &over.blinn}) {
    for (double x : *v) top = std::max(top, x);
  }
  // Up to 3: classic Phong towards grazing can send out more than it receives, without bound.
  axes.top = std::clamp(std::ceil(top * 1.1 * 10.0) / 10.0, 0.1, 3.0);
  draw_axes(list, axes);
  const bool phong_scene = s.model == ShadingModel::phong;
  plot_line(list, axes, *curve, lines.diffuse, kLobeFloor, 2.0f, false);
  plot_line(list, axes, *curve, phong_scene ? lines.phong : lines.blinn,
            phong_scene ? kLobePhong : kLobeBlinn, 4.0f, false);
  plot_line(list, axes, *curve, phong_scene ? lines.blinn : lines.phong,
            phong_scene ? kLobeBlinn : kLobePhong, 1.5f, false);
  if (overlay != nullptr) {
    plot_line(list, axes, *overlay, phong_scene ? over.phong : over.blinn, kLobeOverlay, 2.0f,
              true);
  }
  const double incidence = 90.0 - s.elevation_deg;
  list->AddLine(axes.at(incidence, 0.0), ImVec2(axes.at(incidence, 0.0).x, axes.min.y), kLobeLight,
                1.5f);

  // Legend and figures.
  char text[320];
  float y = axes.max.y + 26.0f;
  const float x = pos.x + 16.0f;
  const AlbedoTerms& normal = curve->front();
  const double closed = s.params.energy_normalize ? 1.0 / kPi : 2.0 / (s.params.phong_alpha + 2.0);
  std::snprintf(text, sizeof text,
                "'%s': the share of a unit directional light's irradiance sent into the "
                "hemisphere",
                s.name.c_str());
  list->AddText(ImVec2(x, y), kLobeText, text);
  y += line;
  std::snprintf(text, sizeof text, "diffuse kd: %.4g at every angle", lines.diffuse.front());
  list->AddText(ImVec2(x, y), kLobeFloor, text);
  y += line;
  std::snprintf(text, sizeof text,
                "Phong (alpha %.4g): %.4f at 0\xC2\xB0 (specular share %.6f; closed form %s = "
                "%.6f)",
                s.params.phong_alpha, lines.phong.front(), normal.phong,
                s.params.energy_normalize ? "1 / pi" : "2 / (alpha + 2)", closed);
  list->AddText(ImVec2(x, y), kLobePhong, text);
  y += line;
  std::snprintf(
      text, sizeof text, "Blinn-Phong (alpha %.4g): %.4f at 0\xC2\xB0, %.4f at %.0f\xC2\xB0",
      s.params.blinn_alpha, lines.blinn.front(), lines.blinn.back(), curve->back().incidence_deg);
  list->AddText(ImVec2(x, y), kLobeBlinn, text);
  y += line;
  if (overlay != nullptr) {
    std::snprintf(text, sizeof text, "dashed: %s, %.4f at 0\xC2\xB0", s.overlay->label.c_str(),
                  (phong_scene ? over.phong : over.blinn).front());
    list->AddText(ImVec2(x, y), kLobeOverlay, text);
    y += line;
  }
  std::snprintf(text, sizeof text,
                "yellow: the light's incidence, %.1f\xC2\xB0; dashed grey at 1: all the light. "
                "Quadrature error (stated) < %.1e%s",
                incidence, lines.error, curves.current() ? "" : "; updating ...");
  list->AddText(ImVec2(x, y), kLobeDim, text);
}

}  // namespace gloss

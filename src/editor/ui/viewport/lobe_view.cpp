// The lobe view (ViewMode::lobe): the selected material's reflected radiance against the outgoing
// angle in the plane of incidence, as a polar plot, Phong and Blinn-Phong overlaid on the diffuse
// floor, and the material's physical reference when it has one, for a light elevation the user
// drags. The values come from analysis/lobe/brdf_lobe.h, which
// evaluates the contract's own functions (shading/shading.h). Drawn with ImDrawList: ImPlot, the
// usual Dear ImGui plotting add-on, is not packaged in Debian 12 (`apt-cache search implot` finds
// nothing), and a half-disc of lines, rings and labels needs none of it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <imgui.h>

#include "analysis/lobe/brdf_lobe.h"
#include "editor/model/document/document.h"
#include "editor/ui/parts/selection.h"
#include "editor/ui/viewport/lobe_plots.h"
#include "editor/ui/viewport/viewport.h"
#include "io/material/preset_table.h"

namespace gloss {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Every 1/8 degree from -90 to 90: a lobe of alpha 1000 is about 3 degrees wide at half height.
constexpr int kSamples = 1441;

const ImU32 kBackground = IM_COL32(24, 24, 28, 255);
const ImU32 kGrid = IM_COL32(62, 62, 70, 255);
const ImU32 kText = IM_COL32(225, 225, 225, 255);
const ImU32 kDim = IM_COL32(150, 150, 158, 255);
const ImU32 kFloorFill = IM_COL32(90, 150, 90, 90);
const ImU32 kFloorLine = IM_COL32(130, 205, 130, 255);
const ImU32 kPhongLine = IM_COL32(255, 150, 40, 255);
const ImU32 kBlinnLine = IM_COL32(80, 190, 255, 255);
const ImU32 kLightLine = IM_COL32(255, 225, 80, 255);
const ImU32 kMirrorLine = IM_COL32(170, 170, 170, 255);
const ImU32 kReferenceLine = IM_COL32(235, 95, 225, 255);

// A log radius spans this many decades below the scale (values under it sit at the origin).
constexpr double kLogDecades = 3.0;

// The polar frame on screen: theta from the normal (up), positive to the right; value 0 at the
// origin, scale at radius_px.
struct PolarFrame {
  ImVec2 origin{0, 0};
  float radius_px = 1.0f;
  double scale = 1.0;
  bool log = false;  // radius log10(value / scale) + kLogDecades, in decades

  // The radius of value as a share of radius_px.
  double share(double value) const {
    if (!log) return value / scale;
    return value > 0.0 ? std::max(std::log10(value / scale) / kLogDecades + 1.0, 0.0) : 0.0;
  }
  ImVec2 at(double theta_deg, double value) const {
    const double t = theta_deg * kPi / 180.0;
    const double r = share(value) * radius_px;
    return ImVec2(origin.x + static_cast<float>(r * std::sin(t)),
                  origin.y - static_cast<float>(r * std::cos(t)));
  }
};

// A ring spacing of 1, 2 or 5 times a power of ten with at most 5 rings up to top (> 0).
double ring_step(double top) {
  const double raw = top / 5.0;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * decade >= raw) return m * decade;
  }
  return 10.0 * decade;
}

void centred_text(ImDrawList* list, ImVec2 at, ImU32 colour, const char* text) {
  const ImVec2 t = ImGui::CalcTextSize(text);
  list->AddText(ImVec2(at.x - t.x * 0.5f, at.y - t.y * 0.5f), colour, text);
}

// The curve of values (one per lobe sample) as a polyline, or dashed (the second material's).
void curve(ImDrawList* list, const PolarFrame& frame, const BrdfLobe& lobe,
           const std::vector<double>& values, ImU32 colour, float thickness, bool dashed = false) {
  std::vector<ImVec2> points;
  points.reserve(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    points.push_back(frame.at(lobe.samples[i].theta_deg, values[i]));
  }
  if (!dashed) {
    list->AddPolyline(points.data(), static_cast<int>(points.size()), colour, 0, thickness);
    return;
  }
  // Dashes of about 8 pixels along the curve, whatever its sampling.
  float run = 0.0f;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const float d = std::hypot(points[i].x - points[i - 1].x, points[i].y - points[i - 1].y);
    if (std::fmod(run, 16.0f) < 8.0f) list->AddLine(points[i - 1], points[i], colour, thickness);
    run += d;
  }
}

// Rings with their values, spokes every 15 degrees with labels every 30, the surface line.
void draw_axes(ImDrawList* list, const PolarFrame& frame, double step) {
  char label[32];
  std::vector<double> rings;
  for (double v = step; v <= frame.scale * 1.0001; v += step) rings.push_back(v);
  if (frame.log) {
    rings.clear();  // one per decade
    for (int d = static_cast<int>(kLogDecades) - 1; d >= 0; --d) {
      rings.push_back(frame.scale * std::pow(10.0, -d));
    }
  }
  for (const double v : rings) {
    const float r = static_cast<float>(frame.share(v) * frame.radius_px);
    list->PathArcTo(frame.origin, r, static_cast<float>(kPi), static_cast<float>(2.0 * kPi), 64);
    list->PathStroke(kGrid, 0, 1.0f);
    std::snprintf(label, sizeof label, "%.3g", v);
    // Values along the surface on the right, under the line.
    list->AddText(
        ImVec2(frame.origin.x + r - ImGui::CalcTextSize(label).x * 0.5f, frame.origin.y + 3.0f),
        kDim, label);
  }
  for (int deg = -90; deg <= 90; deg += 15) {
    list->AddLine(frame.origin, frame.at(deg, frame.scale), kGrid, 1.0f);
    if (deg % 30 != 0) continue;
    std::snprintf(label, sizeof label, "%d\xC2\xB0", deg);
    ImVec2 at = frame.at(deg, frame.scale * (1.0 + 22.0 / frame.radius_px));
    if (deg == -90 || deg == 90) at.y -= 10.0f;  // above the surface line
    centred_text(list, at, kDim, label);
  }
  list->AddLine(ImVec2(frame.origin.x - frame.radius_px - 10.0f, frame.origin.y),
                ImVec2(frame.origin.x + frame.radius_px + 10.0f, frame.origin.y), kDim, 2.0f);
  list->AddText(ImVec2(frame.origin.x - frame.radius_px - 10.0f, frame.origin.y + 3.0f), kDim,
                "surface");
  list->AddText(ImVec2(frame.origin.x + 6.0f, frame.origin.y - frame.radius_px - 40.0f), kDim, "n");
}

// The light's direction (an arrow from the rim towards the point) and the mirror direction.
void draw_directions(ImDrawList* list, const PolarFrame& frame, double elevation_deg) {
  const double incidence = 90.0 - elevation_deg;
  const ImVec2 from = frame.at(-incidence, frame.scale * 1.12);
  const ImVec2 to = frame.at(-incidence, frame.scale * 0.12);
  list->AddLine(from, to, kLightLine, 2.5f);
  const float ax = to.x - from.x, ay = to.y - from.y, len = std::hypot(ax, ay);
  const float ux = ax / len, uy = ay / len;
  list->AddTriangleFilled(to, ImVec2(to.x - 12.0f * ux - 6.0f * uy, to.y - 12.0f * uy + 6.0f * ux),
                          ImVec2(to.x - 12.0f * ux + 6.0f * uy, to.y - 12.0f * uy - 6.0f * ux),
                          kLightLine);
  list->AddCircleFilled(from, 7.0f, kLightLine);
  lobe_dashed_line(list, frame.origin, frame.at(incidence, frame.scale * 1.05), kMirrorLine, 1.5f);
  centred_text(list, frame.at(incidence, frame.scale * 1.05 + 14.0 * frame.scale / frame.radius_px),
               kMirrorLine, "mirror");
}

// Elevation of the light for a cursor at screen point p (the light may be dragged on either
// side; the plot keeps it on the left).
float elevation_at(const PolarFrame& frame, ImVec2 p) {
  const double dx = std::abs(p.x - frame.origin.x), dy = frame.origin.y - p.y;
  const double deg = std::atan2(std::max(dy, 0.0), dx) * 180.0 / kPi;
  return static_cast<float>(std::clamp(deg, 0.0, 90.0));
}

struct Curves {
  std::vector<double> floor, phong, blinn;  // luminance of diffuse, diffuse + specular
  std::vector<double> reference;            // the physical reference's, when there is one
  double top = 0.0;
  std::size_t phong_peak = 0, blinn_peak = 0, reference_peak = 0;
};

Curves luminance_curves(const BrdfLobe& lobe) {
  Curves c;
  for (std::size_t i = 0; i < lobe.samples.size(); ++i) {
    const LobeSample& s = lobe.samples[i];
    c.floor.push_back(luminance(s.diffuse));
    c.phong.push_back(luminance(s.diffuse + s.phong));
    c.blinn.push_back(luminance(s.diffuse + s.blinn));
    if (c.phong[i] > c.phong[c.phong_peak]) c.phong_peak = i;
    if (c.blinn[i] > c.blinn[c.blinn_peak]) c.blinn_peak = i;
    c.top = std::max({c.top, c.phong[i], c.blinn[i]});
    if (!lobe.has_reference) continue;
    c.reference.push_back(luminance(s.reference));
    if (c.reference[i] > c.reference[c.reference_peak]) c.reference_peak = i;
    c.top = std::max(c.top, c.reference[i]);
  }
  return c;
}

void legend_swatch(ImDrawList* list, ImVec2 at, ImU32 colour, bool filled) {
  if (filled) {
    list->AddRectFilled(at, ImVec2(at.x + 22.0f, at.y + 10.0f), kFloorFill);
    list->AddRect(at, ImVec2(at.x + 22.0f, at.y + 10.0f), colour);
  } else {
    list->AddLine(ImVec2(at.x, at.y + 5.0f), ImVec2(at.x + 22.0f, at.y + 5.0f), colour, 3.0f);
  }
}

}  // namespace

void draw_lobe_view(const Scene& scene, const Selection& selection, ViewSettings& view,
                    const Snapshot* snapshot, LobeViewState& state, ImVec2 pos, ImVec2 size) {
  ImDrawList* list = ImGui::GetWindowDrawList();
  list->AddRectFilled(pos, ImVec2(pos.x + size.x, pos.y + size.y), kBackground);
  if (scene.objects.empty()) {
    list->AddText(ImVec2(pos.x + 16.0f, pos.y + 16.0f), kText, "no object to show");
    return;
  }
  const int index = std::clamp(selection.object, 0, static_cast<int>(scene.objects.size()) - 1);
  const Object& object = scene.objects[static_cast<std::size_t>(index)];
  const Material& material = scene.materials[static_cast<std::size_t>(object.material)];
  const std::string material_name =
      static_cast<std::size_t>(object.material) < scene.material_names.size()
          ? scene.material_names[static_cast<std::size_t>(object.material)]
          : "#" + std::to_string(object.material);

  const float pad = 14.0f;
  ImGui::SetCursorScreenPos(ImVec2(pos.x + pad, pos.y + pad));
  const char* what =
      view.lobe_plot == LobePlot::plane        ? "reflected radiance in the plane of incidence"
      : view.lobe_plot == LobePlot::hemisphere ? "reflected radiance over the hemisphere"
                                               : "directional albedo against the incidence angle";
  ImGui::Text("Lobe of material '%s' (object '%s'): %s", material_name.c_str(), object.name.c_str(),
              what);
  ImGui::SetCursorScreenPos(ImVec2(pos.x + pad, ImGui::GetCursorScreenPos().y));
  draw_lobe_controls(view, scene.render.energy_normalize);
  LobeSubject subject;
  subject.material = material;
  subject.name = material_name;
  subject.params = lobe_exponents(material, scene, view);
  subject.model = scene.render.model;
  subject.elevation_deg = view.lobe_elevation_deg;
  subject.overlay = lobe_overlay_material(view, scene, index, snapshot);
  if (subject.overlay) {
    subject.overlay_params = lobe_exponents(subject.overlay->material, scene, view);
  }
  ImGui::SetCursorScreenPos(ImVec2(pos.x + pad, ImGui::GetCursorScreenPos().y));
  draw_lobe_plot_controls(view, scene, snapshot, subject.overlay);
  const float top_y = ImGui::GetCursorScreenPos().y;
  const ImVec2 rest(pos.x, top_y), rest_size(size.x, std::max(size.y - (top_y - pos.y), 40.0f));
  if (view.lobe_plot == LobePlot::hemisphere) {
    draw_lobe_hemisphere(subject, view, rest, rest_size);
    return;
  }
  if (view.lobe_plot == LobePlot::albedo) {
    draw_lobe_albedo(subject, state.albedo, state.overlay_albedo, rest, rest_size);
    return;
  }

  const ShadingModel model = scene.render.model;
  LobeParams params;
  params.elevation_deg = view.lobe_elevation_deg;
  params.phong_alpha = subject.params.phong_alpha;
  params.blinn_alpha = subject.params.blinn_alpha;
  params.energy_normalize = subject.params.energy_normalize;
  params.samples = kSamples;
  const BrdfLobe lobe = sample_brdf_lobe(material, params);
  const Curves curves = luminance_curves(lobe);
  // The second material under the same light, with its own exponents by the same rule.
  LobeParams overlay_params = params;
  overlay_params.phong_alpha = subject.overlay_params.phong_alpha;
  overlay_params.blinn_alpha = subject.overlay_params.blinn_alpha;
  const BrdfLobe overlay_lobe =
      subject.overlay ? sample_brdf_lobe(subject.overlay->material, overlay_params) : BrdfLobe{};
  const Curves overlay = luminance_curves(overlay_lobe);
  const double top = std::max(curves.top, overlay.top);

  // Layout: the half disc above the surface line, the legend under it.
  const float legend_h = 14.0f * (ImGui::GetTextLineHeightWithSpacing() + 2.0f) + 20.0f;
  const float plot_h = std::max(size.y - (top_y - pos.y) - legend_h - 60.0f, 40.0f);
  PolarFrame frame;
  frame.radius_px = std::max(std::min(size.x * 0.5f - 70.0f, plot_h), 20.0f);
  frame.origin =
      ImVec2(std::floor(pos.x + size.x * 0.5f), std::floor(top_y + 44.0f + frame.radius_px));
  const double step = ring_step(std::max(top, 1e-6) * 1.05);
  frame.scale = step * std::ceil(std::max(top, 1e-6) * 1.05 / step);
  frame.log = view.lobe_log_radius;

  // The floor: a filled half disc of radius kd ndl (the same in every direction).
  const double floor_value = curves.floor.empty() ? 0.0 : curves.floor.front();
  const float floor_r = static_cast<float>(frame.share(floor_value) * frame.radius_px);
  if (floor_r > 0.5f) {
    list->PathArcTo(frame.origin, floor_r, static_cast<float>(kPi), static_cast<float>(2.0 * kPi),
                    64);
    list->PathFillConvex(kFloorFill);
  }
  draw_axes(list, frame, step);
  curve(list, frame, lobe, curves.floor, kFloorLine, 2.0f);
  const bool phong_scene = model == ShadingModel::phong;
  // The scene's model wide underneath, the other one narrow on top: where the two coincide (the
  // 4x rule makes them close near the peak) both colours stay visible.
  curve(list, frame, lobe, phong_scene ? curves.phong : curves.blinn,
        phong_scene ? kPhongLine : kBlinnLine, 4.5f);
  curve(list, frame, lobe, phong_scene ? curves.blinn : curves.phong,
        phong_scene ? kBlinnLine : kPhongLine, 1.5f);
  if (lobe.has_reference) curve(list, frame, lobe, curves.reference, kReferenceLine, 2.5f);
  if (subject.overlay) {
    curve(list, frame, overlay_lobe, overlay.floor, kLobeOverlay, 1.0f, true);
    curve(list, frame, overlay_lobe, phong_scene ? overlay.phong : overlay.blinn, kLobeOverlay,
          2.0f, true);
  }
  draw_directions(list, frame, params.elevation_deg);

  // Dragging in the plot moves the light; hovering reads the values at that angle.
  const ImVec2 plot_min(frame.origin.x - frame.radius_px - 40.0f,
                        frame.origin.y - frame.radius_px - 40.0f);
  ImGui::SetCursorScreenPos(plot_min);
  ImGui::InvisibleButton("##lobe-plot",
                         ImVec2(2.0f * frame.radius_px + 80.0f, frame.radius_px + 44.0f));
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  if (ImGui::IsItemActive()) view.lobe_elevation_deg = elevation_at(frame, mouse);
  // The readout: at the hovered angle, else at the mirror direction.
  const bool hovered = ImGui::IsItemHovered() && !ImGui::IsItemActive();
  const double theta =
      hovered
          ? std::clamp(std::atan2(mouse.x - frame.origin.x, frame.origin.y - mouse.y) * 180.0 / kPi,
                       -90.0, 90.0)
          : 90.0 - params.elevation_deg;
  if (hovered) {
    list->AddLine(frame.origin, frame.at(theta, frame.scale), IM_COL32(255, 255, 255, 120), 1.0f);
  }
  const LobeSample readout = lobe_sample(material, params, theta);

  // Legend and values.
  float y = frame.origin.y + 30.0f;
  const float x = pos.x + pad + 8.0f;
  const float line_h = ImGui::GetTextLineHeightWithSpacing() + 2.0f;
  char text[256];
  legend_swatch(list, ImVec2(x, y + 2.0f), kFloorLine, true);
  std::snprintf(text, sizeof text, "diffuse floor  kd ndl = %.4g  (ndl = sin %.1f\xC2\xB0 = %.4f)",
                floor_value, params.elevation_deg, std::sin(params.elevation_deg * kPi / 180.0));
  list->AddText(ImVec2(x + 30.0f, y), kText, text);
  y += line_h;
  const LobeSample& pp = lobe.samples[curves.phong_peak];
  const LobeSample& bp = lobe.samples[curves.blinn_peak];
  legend_swatch(list, ImVec2(x, y + 2.0f), kPhongLine, false);
  std::snprintf(text, sizeof text,
                "Phong (R.V)%s  alpha %.4g  energy x %.4g   peak %.4g at %.1f\xC2\xB0",
                phong_scene ? ", the scene's model," : "", params.phong_alpha, lobe.phong_norm,
                curves.phong[curves.phong_peak], pp.theta_deg);
  list->AddText(ImVec2(x + 30.0f, y), kText, text);
  y += line_h;
  legend_swatch(list, ImVec2(x, y + 2.0f), kBlinnLine, false);
  std::snprintf(text, sizeof text,
                "Blinn-Phong (N.H)%s  alpha %.4g  energy x %.4g   peak %.4g at %.1f\xC2\xB0",
                phong_scene ? "" : ", the scene's model,", params.blinn_alpha, lobe.blinn_norm,
                curves.blinn[curves.blinn_peak], bp.theta_deg);
  list->AddText(ImVec2(x + 30.0f, y), kText, text);
  y += line_h;
  if (lobe.has_reference) {
    const PhysicalReference& r = *material.reference;
    legend_swatch(list, ImVec2(x, y + 2.0f), kReferenceLine, false);
    std::snprintf(text, sizeof text,
                  "physical reference: %s, roughness %.3g (GGX; Reference panel)   peak %.4g at "
                  "%.1f\xC2\xB0",
                  to_string(r.kind), r.roughness, curves.reference[curves.reference_peak],
                  lobe.samples[curves.reference_peak].theta_deg);
    list->AddText(ImVec2(x + 30.0f, y), kText, text);
    y += line_h;
  }
  if (subject.overlay) {
    legend_swatch(list, ImVec2(x, y + 2.0f), kLobeOverlay, false);
    const std::vector<double>& o = phong_scene ? overlay.phong : overlay.blinn;
    const std::size_t peak = phong_scene ? overlay.phong_peak : overlay.blinn_peak;
    std::snprintf(text, sizeof text, "dashed: %s  alpha %.4g   peak %.4g at %.1f\xC2\xB0",
                  subject.overlay->label.c_str(),
                  phong_scene ? overlay_params.phong_alpha : overlay_params.blinn_alpha, o[peak],
                  overlay_lobe.samples[peak].theta_deg);
    list->AddText(ImVec2(x + 30.0f, y), kLobeOverlay, text);
    y += line_h;
  }
  legend_swatch(list, ImVec2(x, y + 2.0f), kLightLine, false);
  std::snprintf(text, sizeof text,
                "light: %.1f\xC2\xB0 above the surface (incidence %.1f\xC2\xB0);"
                " dashed: mirror direction",
                params.elevation_deg, 90.0 - params.elevation_deg);
  list->AddText(ImVec2(x + 30.0f, y), kText, text);
  y += line_h;
  list->AddText(
      ImVec2(x, y), kDim,
      "Radius: luminance (Rec. 709) of the radiance reflected towards each outgoing angle,"
      " diffuse + specular,");
  y += line_h;
  list->AddText(ImVec2(x, y), kDim,
                "for one point light of unit colours (Ld = Ls = 1, no attenuation, not shadowed);"
                " ks colours the lobe.");
  y += line_h + 4.0f;
  const LobeSample& s = readout;
  std::snprintf(text, sizeof text,
                "at %.1f\xC2\xB0 from the normal%s (drag in the plot to move the light):", theta,
                hovered ? "" : " (the mirror direction; hover the plot for others)");
  list->AddText(ImVec2(x, y), kText, text);
  y += line_h;
  std::snprintf(text, sizeof text, "  diffuse  RGB %.4g %.4g %.4g", s.diffuse.x, s.diffuse.y,
                s.diffuse.z);
  list->AddText(ImVec2(x, y), kFloorLine, text);
  y += line_h;
  std::snprintf(text, sizeof text, "  Phong specular  RGB %.4g %.4g %.4g   c = R.V = %.5f",
                s.phong.x, s.phong.y, s.phong.z, s.cos_phong);
  list->AddText(ImVec2(x, y), kPhongLine, text);
  y += line_h;
  std::snprintf(text, sizeof text, "  Blinn-Phong specular  RGB %.4g %.4g %.4g   c = N.H = %.5f",
                s.blinn.x, s.blinn.y, s.blinn.z, s.cos_blinn);
  list->AddText(ImVec2(x, y), kBlinnLine, text);
  if (lobe.has_reference) {
    y += line_h;
    std::snprintf(text, sizeof text, "  reference  RGB %.4g %.4g %.4g  (pi f ndl)", s.reference.x,
                  s.reference.y, s.reference.z);
    list->AddText(ImVec2(x, y), kReferenceLine, text);
  }
}

}  // namespace gloss

// The lobe view's 3D plot: the radiance a surface point sends towards every outgoing direction
// of the hemisphere, under the lobe view's light, as a surface of radius L(v) in direction v,
// drawn as a wire mesh with Dear ImGui's draw lists (an orthographic view turned by dragging).
// The mesh is laid out about the mirror direction, its rings gathering at it, so that even a
// lobe of alpha 10^4 (under a degree wide) has rings on it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>

#include "analysis/lobe/brdf_lobe.h"
#include "editor/ui/viewport/lobe_plots.h"

namespace gloss {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kRings = 40;      // angles from the mirror direction, 0 to 180 degrees
constexpr int kMeridians = 48;  // about it
constexpr ImU32 kSurfaceLine = IM_COL32(120, 120, 130, 255);

double radians(double degrees) {
  return degrees * kPi / 180.0;
}

// The orthographic view: turned about the normal by azimuth, then tilted down by tilt.
struct View3d {
  ImVec2 centre{0, 0};
  double scale = 1.0;  // pixels per unit of radiance
  double azimuth = 0.0, tilt = 0.0;

  ImVec2 at(const glm::dvec3& p) const {
    const double ca = std::cos(azimuth), sa = std::sin(azimuth);
    const double x = p.x * ca - p.z * sa, z = p.x * sa + p.z * ca;
    const double up = p.y * std::cos(tilt) - z * std::sin(tilt);
    return ImVec2(centre.x + static_cast<float>(x * scale),
                  centre.y - static_cast<float>(up * scale));
  }
};

// The mesh's directions: ring i at angle psi_i = 180 (i / kRings)^2 degrees from the mirror
// direction r, meridian j at azimuth 360 j / kMeridians about it.
glm::dvec3 direction(const glm::dvec3& r, int ring, int meridian) {
  const double psi = kPi * std::pow(static_cast<double>(ring) / kRings, 2.0);
  const double phi = 2.0 * kPi * meridian / kMeridians;
  const glm::dvec3 b1(r.y, -r.x, 0.0), b2(0.0, 0.0, 1.0);  // r lies in the x-y plane
  return std::cos(psi) * r + std::sin(psi) * (std::cos(phi) * b1 + std::sin(phi) * b2);
}

// Radiance towards every mesh direction (luminance; < 0 below the surface).
std::vector<double> radiance_mesh(const Material& m, const AlbedoParams& params, ShadingModel model,
                                  const glm::dvec3& l, const glm::dvec3& r, double& largest) {
  std::vector<double> mesh;
  mesh.reserve(static_cast<std::size_t>((kRings + 1) * kMeridians));
  for (int i = 0; i <= kRings; ++i) {
    for (int j = 0; j < kMeridians; ++j) {
      const glm::dvec3 v = direction(r, i, j);
      if (v.y <= 0.0) {
        mesh.push_back(-1.0);
        continue;
      }
      const LobeWeights w = lobe_weights(params, l, v);
      const double spec = model == ShadingModel::phong ? w.phong : w.blinn;
      const double value =
          luminance(glm::dvec3(m.diffuse) * w.diffuse + glm::dvec3(m.specular) * spec);
      largest = std::max(largest, value);
      mesh.push_back(value);
    }
  }
  return mesh;
}

void draw_mesh(ImDrawList* list, const View3d& view, const std::vector<double>& mesh,
               const glm::dvec3& r, ImU32 colour, bool dashed) {
  auto point = [&](int i, int j) {
    const double value = mesh[static_cast<std::size_t>(i * kMeridians + (j % kMeridians))];
    return std::make_pair(value >= 0.0, view.at(direction(r, i, j % kMeridians) * value));
  };
  auto segment = [&](std::pair<bool, ImVec2> a, std::pair<bool, ImVec2> b, float width) {
    if (!a.first || !b.first) return;
    if (dashed) {
      lobe_dashed_line(list, a.second, b.second, colour, width);
    } else {
      list->AddLine(a.second, b.second, colour, width);
    }
  };
  for (int j = 0; j < kMeridians; j += 2) {  // meridians, from the peak outwards
    for (int i = 0; i < kRings; ++i) segment(point(i, j), point(i + 1, j), 1.2f);
  }
  for (int i = 2; i <= kRings; i += 2) {  // rings
    for (int j = 0; j < kMeridians; ++j) segment(point(i, j), point(i, j + 1), 1.0f);
  }
}

}  // namespace

void draw_lobe_hemisphere(const LobeSubject& s, ViewSettings& view, ImVec2 pos, ImVec2 size) {
  ImDrawList* list = ImGui::GetWindowDrawList();
  const double e = radians(s.elevation_deg);
  const glm::dvec3 l(-std::cos(e), std::sin(e), 0.0), r(std::cos(e), std::sin(e), 0.0);
  double largest = 0.0;
  const std::vector<double> mesh = radiance_mesh(s.material, s.params, s.model, l, r, largest);
  std::vector<double> overlay;
  if (s.overlay) {
    overlay = radiance_mesh(s.overlay->material, s.overlay_params, s.model, l, r, largest);
  }
  const float legend_h = 3.0f * ImGui::GetTextLineHeightWithSpacing() + 12.0f;
  const float plot_h = std::max(size.y - legend_h, 40.0f);
  View3d v;
  v.azimuth = radians(view.lobe_azimuth_deg);
  v.tilt = radians(view.lobe_tilt_deg);
  const float radius_px = std::max(std::min(size.x * 0.45f, plot_h * 0.5f) - 10.0f, 20.0f);
  v.scale = radius_px / std::max(largest, 1e-9);
  v.centre = ImVec2(std::floor(pos.x + size.x * 0.5f), std::floor(pos.y + plot_h * 0.62f));

  // The surface: a disc of the largest radius, its rim as the ellipse the view makes of it.
  std::vector<ImVec2> rim;
  for (int k = 0; k <= 72; ++k) {
    const double a = 2.0 * kPi * k / 72;
    rim.push_back(v.at(glm::dvec3(std::cos(a), 0.0, std::sin(a)) * largest));
  }
  list->AddPolyline(rim.data(), static_cast<int>(rim.size()), kSurfaceLine, 0, 1.0f);
  list->AddLine(v.at(glm::dvec3(-largest, 0, 0)), v.at(glm::dvec3(largest, 0, 0)), kLobeGrid, 1.0f);
  list->AddLine(v.at(glm::dvec3(0, 0, -largest)), v.at(glm::dvec3(0, 0, largest)), kLobeGrid, 1.0f);
  list->AddLine(v.at(glm::dvec3(0.0)), v.at(glm::dvec3(0.0, 1.1 * largest, 0.0)), kLobeDim, 1.0f);
  list->AddText(v.at(glm::dvec3(0.0, 1.15 * largest, 0.0)), kLobeDim, "n");
  const ImU32 colour = s.model == ShadingModel::phong ? kLobePhong : kLobeBlinn;
  draw_mesh(list, v, mesh, r, colour, false);
  if (s.overlay) draw_mesh(list, v, overlay, r, kLobeOverlay, true);
  // The light, an arrow towards the point, and the mirror direction.
  const ImVec2 from = v.at(l * 1.2 * largest), to = v.at(l * 0.15 * largest);
  list->AddLine(from, to, kLobeLight, 2.5f);
  list->AddCircleFilled(from, 6.0f, kLobeLight);
  lobe_dashed_line(list, v.at(glm::dvec3(0.0)), v.at(r * 1.1 * largest), kLobeDim, 1.5f);

  // Dragging in the plot turns the view.
  ImGui::SetCursorScreenPos(pos);
  ImGui::InvisibleButton("##lobe-3d", ImVec2(size.x, plot_h));
  if (ImGui::IsItemActive()) {
    const ImVec2 d = ImGui::GetIO().MouseDelta;
    view.lobe_azimuth_deg = std::fmod(view.lobe_azimuth_deg + d.x * 0.4f + 360.0f, 360.0f);
    view.lobe_tilt_deg = std::clamp(view.lobe_tilt_deg + d.y * 0.4f, -10.0f, 89.0f);
  }
  if (ImGui::IsItemHovered()) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeAll);

  char text[256];
  float y = pos.y + plot_h + 4.0f;
  const float x = pos.x + 8.0f;
  const double alpha = s.model == ShadingModel::phong ? s.params.phong_alpha : s.params.blinn_alpha;
  std::snprintf(text, sizeof text,
                "%s, alpha %.4g: radius = luminance of the radiance towards each direction "
                "(diffuse + specular), largest %.4g",
                s.model == ShadingModel::phong ? "Phong" : "Blinn-Phong", alpha, largest);
  list->AddText(ImVec2(x, y), colour, text);
  y += ImGui::GetTextLineHeightWithSpacing();
  if (s.overlay) {
    std::snprintf(text, sizeof text, "dashed: %s, alpha %.4g", s.overlay->label.c_str(),
                  s.model == ShadingModel::phong ? s.overlay_params.phong_alpha
                                                 : s.overlay_params.blinn_alpha);
    list->AddText(ImVec2(x, y), kLobeOverlay, text);
    y += ImGui::GetTextLineHeightWithSpacing();
  }
  std::snprintf(text, sizeof text,
                "light %.1f\xC2\xB0 above the surface (yellow); dashed grey: mirror direction; "
                "drag to turn (azimuth %.0f\xC2\xB0, tilt %.0f\xC2\xB0)",
                s.elevation_deg, view.lobe_azimuth_deg, view.lobe_tilt_deg);
  list->AddText(ImVec2(x, y), kLobeDim, text);
}

}  // namespace gloss

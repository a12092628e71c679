// The Quality window's plot: every measured row as a point, RMSE against the exact reference
// (log) over its median time (log), as scripts/plot_tradeoff.py draws gloss-cli tradeoff's CSV:
// CPU knobs as discs, the raster (GLSL) rows as squares, one colour per knob. Drawn with
// ImDrawList (ImPlot is not packaged in Debian 12; see lobe_view.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <imgui.h>

#include "editor/ui/panels/panel_state.h"
#include "editor/ui/panels/quality_parts.h"

namespace gloss {

namespace {

const ImU32 kBackground = IM_COL32(24, 24, 28, 255);
const ImU32 kGrid = IM_COL32(62, 62, 70, 255);
const ImU32 kDim = IM_COL32(150, 150, 158, 255);

// Okabe-Ito colours (as plot_tradeoff.py) for the CPU knobs, then the raster knobs'.
const ImU32 kColours[] = {
    IM_COL32(0, 114, 178, 255),   IM_COL32(160, 134, 0, 255),   IM_COL32(230, 159, 0, 255),
    IM_COL32(0, 158, 115, 255),   IM_COL32(204, 121, 167, 255), IM_COL32(213, 94, 0, 255),
    IM_COL32(86, 180, 233, 255),  IM_COL32(220, 220, 220, 255), IM_COL32(255, 80, 80, 255),
    IM_COL32(120, 220, 120, 255), IM_COL32(180, 140, 255, 255), IM_COL32(255, 200, 90, 255),
    IM_COL32(90, 220, 220, 255)};

struct Point {
  std::string knob, label;
  double time_ms, rmse;
  bool raster;
};

std::vector<Point> points_of(const QualityState& quality) {
  std::vector<Point> points;
  for (const TradeoffRow& r : quality.cpu.rows()) {
    points.push_back({to_string(r.knob), std::string(to_string(r.knob)) + " " + r.setting,
                      r.time_ms, r.error.rmse, false});
  }
  for (const RasterTradeoffRow& r : quality.raster.rows()) {
    points.push_back({r.knob, r.knob + " " + r.setting, r.time_ms, r.error.rmse, r.knob != "cpu"});
  }
  return points;
}

}  // namespace

void draw_quality_plot(const QualityState& quality, float height) {
  const std::vector<Point> points = points_of(quality);
  if (points.empty()) return;
  std::vector<std::string> knobs;  // legend order: first appearance
  double t0 = 1e300, t1 = 0, e0 = 1e300, e1 = 0;
  for (const Point& p : points) {
    if (std::find(knobs.begin(), knobs.end(), p.knob) == knobs.end()) knobs.push_back(p.knob);
    t0 = std::min(t0, p.time_ms);
    t1 = std::max(t1, p.time_ms);
    if (p.rmse > 0) e0 = std::min(e0, p.rmse);
    e1 = std::max(e1, p.rmse);
  }
  // Whole decades around the points, with a margin so that none sits on an edge; an exact
  // match (rmse 0) sits on the bottom edge.
  if (e0 >= 1e300) e0 = 1e-4;
  const double lt0 = std::floor(std::log10(std::max(t0, 1e-3)) - 0.15);
  const double lt1 = std::ceil(std::log10(std::max(t1, 1e-3)) + 0.15);
  const double le0 = std::floor(std::log10(e0) - 0.15);
  const double le1 = std::ceil(std::log10(std::max(e1, e0)) + 0.15);

  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float width = ImGui::GetContentRegionAvail().x;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float left = 44.0f, bottom = 18.0f;
  const ImVec2 p0(origin.x + left, origin.y + 4.0f);
  const ImVec2 p1(origin.x + width - 6.0f, origin.y + height - bottom);
  draw->AddRectFilled(p0, p1, kBackground);
  auto x_of = [&](double t) {
    const double f = (std::log10(std::max(t, 1e-3)) - lt0) / (lt1 - lt0);
    return p0.x + static_cast<float>(f) * (p1.x - p0.x);
  };
  auto y_of = [&](double e) {
    const double f = e > 0 ? (std::log10(e) - le0) / (le1 - le0) : 0.0;
    return p1.y - static_cast<float>(std::clamp(f, 0.0, 1.0)) * (p1.y - p0.y);
  };
  char text[32];
  for (double d = lt0; d <= lt1; d += 1) {
    const float x = x_of(std::pow(10.0, d));
    draw->AddLine(ImVec2(x, p0.y), ImVec2(x, p1.y), kGrid);
    std::snprintf(text, sizeof text, "%g ms", std::pow(10.0, d));
    draw->AddText(ImVec2(x - 12.0f, p1.y + 2.0f), kDim, text);
  }
  for (double d = le0; d <= le1; d += 1) {
    const float y = y_of(std::pow(10.0, d));
    draw->AddLine(ImVec2(p0.x, y), ImVec2(p1.x, y), kGrid);
    std::snprintf(text, sizeof text, "1e%d", static_cast<int>(d));
    draw->AddText(ImVec2(origin.x + 2.0f, y - 7.0f), kDim, text);
  }
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const Point* hovered = nullptr;
  float nearest = 36.0f;  // squared pixels: within 6 px
  for (const Point& p : points) {
    const std::size_t k =
        static_cast<std::size_t>(std::find(knobs.begin(), knobs.end(), p.knob) - knobs.begin());
    const ImU32 colour = kColours[k % (sizeof kColours / sizeof kColours[0])];
    const ImVec2 c(x_of(p.time_ms), y_of(p.rmse));
    if (p.raster) {
      draw->AddRectFilled(ImVec2(c.x - 3.5f, c.y - 3.5f), ImVec2(c.x + 3.5f, c.y + 3.5f), colour);
    } else {
      draw->AddCircleFilled(c, 3.5f, colour);
    }
    const float d2 = (mouse.x - c.x) * (mouse.x - c.x) + (mouse.y - c.y) * (mouse.y - c.y);
    if (d2 < nearest) {
      nearest = d2;
      hovered = &p;
    }
  }
  ImGui::Dummy(ImVec2(width, height));
  if (hovered != nullptr && ImGui::IsItemHovered()) {
    ImGui::SetTooltip("%s: %.2f ms, RMSE %.4g", hovered->label.c_str(), hovered->time_ms,
                      hovered->rmse);
  }
  // Legend: one swatch per knob, wrapped to the width.
  for (std::size_t k = 0; k < knobs.size(); ++k) {
    const ImU32 colour = kColours[k % (sizeof kColours / sizeof kColours[0])];
    const float w = ImGui::CalcTextSize(knobs[k].c_str()).x + 16.0f;
    if (k > 0) {
      ImGui::SameLine();
      if (ImGui::GetCursorPosX() + w > ImGui::GetWindowContentRegionMax().x) ImGui::NewLine();
    }
    const ImVec2 at = ImGui::GetCursorScreenPos();
    draw->AddRectFilled(ImVec2(at.x, at.y + 4.0f), ImVec2(at.x + 8.0f, at.y + 12.0f), colour);
    ImGui::Dummy(ImVec2(10.0f, 1.0f));
    ImGui::SameLine(0.0f, 2.0f);
    ImGui::TextDisabled("%s", knobs[k].c_str());
  }
  ImGui::TextDisabled("RMSE (log) against ms (log); discs: CPU rows, squares: raster rows");
}

}  // namespace gloss

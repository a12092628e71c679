// The Quality window's raster (GLSL) rows (issue 12, item 5): the raster path's knobs measured
// against the same reference as the CPU rows above them (editor/gl/raster/raster_tradeoff.h). The
// CPU part runs on a worker; the raster frames are drawn on this, the UI thread, in slices of
// kRasterQualitySliceMs per frame (run_frame calls RasterTradeoff::step), because GL calls must
// stay on the thread that owns the context.
#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "editor/ui/panels/panel_state.h"
#include "editor/ui/panels/panel_widgets.h"
#include "editor/ui/panels/quality_parts.h"
#include "editor/ui/parts/commands.h"
#include "editor/ui/parts/open_windows.h"

namespace gloss {

namespace {

const char* state_text(const RasterTradeoff& r) {
  switch (r.state()) {
    case RasterTradeoff::State::idle:
      return "not measured yet";
    case RasterTradeoff::State::references:
      return "rendering the references on a worker";
    case RasterTradeoff::State::rendering:
      return "drawing raster frames";
    case RasterTradeoff::State::done:
      return "measured";
    case RasterTradeoff::State::cancelled:
      return "cancelled";
    case RasterTradeoff::State::failed:
      return "failed";
  }
  return "";
}

void draw_rows(const std::vector<RasterTradeoffRow>& rows) {
  const ImGuiTableFlags flags =
      ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV;
  if (!ImGui::BeginTable("raster rows", 8, flags)) return;
  auto width = [](const char* widest) { return ImGui::CalcTextSize(widest).x; };
  ImGui::TableSetupColumn("knob", ImGuiTableColumnFlags_WidthFixed, width("tessellation"));
  ImGui::TableSetupColumn("setting", ImGuiTableColumnFlags_WidthFixed, width("pixel 32 (b)"));
  ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthFixed, width("12345"));
  ImGui::TableSetupColumn("draw", ImGuiTableColumnFlags_WidthFixed, width("12345"));
  ImGui::TableSetupColumn("shadow", ImGuiTableColumnFlags_WidthFixed, width("shadow"));
  ImGui::TableSetupColumn("RMSE", ImGuiTableColumnFlags_WidthFixed, width("0.0000"));
  ImGui::TableSetupColumn("% off", ImGuiTableColumnFlags_WidthFixed, width("100.00"));
  ImGui::TableSetupColumn("% agree", ImGuiTableColumnFlags_WidthFixed, width("% agree"));
  ImGui::TableHeadersRow();
  for (const RasterTradeoffRow& r : rows) {
    const bool cpu = r.knob == "cpu";
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    // "raster-shadow-map" -> "shadow map": the section says these are raster rows.
    std::string knob = r.knob.rfind("raster-", 0) == 0 ? r.knob.substr(7) : r.knob;
    for (char& c : knob) c = c == '-' ? ' ' : c;
    ImGui::TextUnformatted(knob.c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%s%s", r.setting.c_str(), r.base_setting ? " (b)" : "");
    ImGui::TableNextColumn();
    ImGui::Text(r.time_ms < 10.0 ? "%.2f" : "%.0f", r.time_ms);
    ImGui::TableNextColumn();
    if (cpu) {
      ImGui::TextDisabled("-");
    } else {
      ImGui::Text(r.draw_ms < 10.0 ? "%.2f" : "%.0f", r.draw_ms);
    }
    ImGui::TableNextColumn();
    if (cpu || r.shadow_ms == 0.0) {
      ImGui::TextDisabled("-");
    } else {
      ImGui::Text(r.shadow_ms < 10.0 ? "%.2f" : "%.0f", r.shadow_ms);
    }
    ImGui::TableNextColumn();
    ImGui::Text("%.4f", r.error.rmse);
    ImGui::TableNextColumn();
    ImGui::Text("%.2f", r.error.pct_pixels_off);
    ImGui::TableNextColumn();
    ImGui::Text("%.2f", r.pct_agree);
  }
  ImGui::EndTable();
}

}  // namespace

void start_raster_quality(QualityState& quality, OpenWindows& windows, const Scene& scene,
                          int width, int height, int reference_spp) {
  RasterTradeoffOptions options = raster_options_like(quick_tradeoff_options());
  if (width > 0 && height > 0) {
    options.width = width;
    options.height = height;
  }
  if (reference_spp > 0) options.reference_spp = reference_spp;
  quality.raster.start(scene, options);
  windows.quality = true;
  quality.show_raster_rows = true;
}

void draw_raster_quality_section(QualityState& quality, OpenWindows& windows, Commands& commands) {
  RasterTradeoff& r = quality.raster;
  if (r.running()) {
    if (ImGui::Button("Cancel##raster", ImVec2(120, 0))) r.cancel();
  } else if (ImGui::Button("Measure raster", ImVec2(120, 0))) {
    try {
      start_raster_quality(quality, windows, commands.scene());
    } catch (const std::exception& e) {
      commands.error(std::string("raster quality: ") + e.what());
    }
  }
  if (ImGui::IsItemHovered() && !r.running()) {
    const TradeoffOptions quick = quick_tradeoff_options();
    ImGui::SetTooltip(
        "the raster path's shading frequency, shadow map size and bias and (teapots) mesh "
        "resolution, against the CPU rows' reference (%d px wide, %d spp, double) and a cpu "
        "1-spp row; the raster frames are drawn on the UI thread between its frames, so the "
        "window is slow until they are done",
        quick.width, quick.reference_spp);
  }
  ImGui::SameLine();
  char overlay[160];
  if (r.state() == RasterTradeoff::State::idle) {
    std::snprintf(overlay, sizeof overlay, "%s", state_text(r));
  } else {
    std::snprintf(overlay, sizeof overlay, "%s, %.1f s, %dx%d px", state_text(r), r.elapsed_s(),
                  r.width(), r.height());
  }
  ImGui::ProgressBar(static_cast<float>(r.progress()), ImVec2(-1.0f, 0.0f), overlay);
  if (r.state() == RasterTradeoff::State::failed) {
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", r.error().c_str());
  }
  if (!r.rows().empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled(
        "ms: a frame with meshes and shadow maps kept (a camera drag), total read back; "
        "shadow: the shadow pass a light drag adds; %% agree: pixels within 1e-3 of the 1-spp "
        "exact image; (b): the raster base.");
    ImGui::PopTextWrapPos();
    draw_rows(r.rows());
    ImGui::Spacing();
    draw_quality_plot(quality, 200.0f);
  }
  if (r.state() != RasterTradeoff::State::idle) {
    ImGui::PushTextWrapPos(0.0f);
    for (const std::string& note : r.notes()) ImGui::TextDisabled("%s", note.c_str());
    ImGui::PopTextWrapPos();
  }
}

}  // namespace gloss

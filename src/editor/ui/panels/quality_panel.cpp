// The Quality window: for the scene on screen, what each accuracy knob costs (median render time)
// and buys (error against a double-precision reference), from a quick measurement the user starts
// (quality_measurement.h). The measurement runs on a worker over a copy of the scene; an edit
// while it runs or after it does not cancel it, it marks the results stale. "Use" buttons emit
// commands (target spp, shadows, pow) or set the viewport's preview scale, a view preference.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include <imgui.h>

#include "editor/ui/panels/panel_state.h"
#include "editor/ui/panels/panel_widgets.h"
#include "editor/ui/panels/panels.h"
#include "editor/ui/panels/quality_parts.h"
#include "editor/ui/parts/commands.h"
#include "editor/ui/parts/open_windows.h"

namespace gloss {

namespace {

const char* state_text(const QualityMeasurement& q) {
  switch (q.state()) {
    case QualityMeasurement::State::idle:
      return "not measured yet";
    case QualityMeasurement::State::running:
      return "measuring";
    case QualityMeasurement::State::done:
      return "measured";
    case QualityMeasurement::State::cancelled:
      return "cancelled";
    case QualityMeasurement::State::failed:
      return "failed";
  }
  return "";
}

void draw_controls(QualityMeasurement& q, Commands& commands) {
  if (q.running()) {
    if (ImGui::Button("Cancel", ImVec2(90, 0))) q.cancel();
  } else if (ImGui::Button("Measure", ImVec2(90, 0))) {
    try {
      q.start(commands.scene());
    } catch (const std::exception& e) {
      commands.error(std::string("quality: ") + e.what());
    }
  }
  if (ImGui::IsItemHovered() && !q.running()) {
    ImGui::SetTooltip(
        "renders every setting of every knob on a worker thread: %d px wide, %d runs "
        "each (median), reference %d spp in double precision",
        quick_tradeoff_options().width, quick_tradeoff_options().runs,
        quick_tradeoff_options().reference_spp);
  }
  ImGui::SameLine();
  const int total = static_cast<int>(q.knobs().size());
  const int done = q.knobs_done();
  char overlay[128];
  if (q.running()) {
    const std::optional<Knob> current = q.current_knob();
    std::snprintf(overlay, sizeof overlay, "%s: knob %d of %d, %.1f s",
                  current ? to_string(*current) : "", std::min(done + 1, total), total,
                  q.elapsed_s());
  } else if (q.state() == QualityMeasurement::State::idle) {
    std::snprintf(overlay, sizeof overlay, "%s", state_text(q));
  } else {
    std::snprintf(overlay, sizeof overlay, "%s: %d of %d knobs in %.1f s, %dx%d px", state_text(q),
                  done, total, q.elapsed_s(), q.width(), q.height());
  }
  const float fraction = total > 0 ? static_cast<float>(done) / static_cast<float>(total) : 0.0f;
  ImGui::ProgressBar(fraction, ImVec2(-1.0f, 0.0f), overlay);
  if (q.state() == QualityMeasurement::State::failed) {
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", q.error().c_str());
  }
  if (q.stale(commands.scene())) {
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f),
                       "stale: the scene changed since it was measured; Measure again");
  }
}

// The Use cell of one row: "in use", a button, or nothing when the editor lacks the knob.
void draw_use(Commands& commands, ViewSettings& view, const TradeoffRow& row) {
  const Scene& scene = commands.scene();
  if (row_in_use(row, scene, view.preview_scale)) {
    ImGui::TextDisabled("in use");
    return;
  }
  if (std::optional<Command> command = command_for_row(row, scene)) {
    if (ImGui::SmallButton("Use")) commands.execute(*command);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", command_label(*command).c_str());
  } else if (std::optional<float> scale = preview_scale_for_row(row)) {
    if (ImGui::SmallButton("Use")) view.preview_scale = *scale;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("set the preview scale to %.2f", *scale);
  }
}

void draw_knob_table(Commands& commands, ViewSettings& view, Knob knob,
                     const std::vector<TradeoffRow>& rows) {
  const ImGuiTableFlags flags =
      ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV;
  if (!ImGui::BeginTable(to_string(knob), 7, flags)) return;
  // Widths of the widest expected cell, so that the knobs' tables line up.
  auto width = [](const char* widest) { return ImGui::CalcTextSize(widest).x; };
  ImGui::TableSetupColumn("setting", ImGuiTableColumnFlags_WidthFixed, width("per-pixel"));
  ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthFixed, width("12345"));
  ImGui::TableSetupColumn("RMSE", ImGuiTableColumnFlags_WidthFixed, width("0.0000"));
  ImGui::TableSetupColumn("PSNR dB", ImGuiTableColumnFlags_WidthFixed, width("PSNR dB"));
  ImGui::TableSetupColumn("% off", ImGuiTableColumnFlags_WidthFixed, width("100.00"));
  ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, width("ref, base"));
  ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, width("in use"));
  ImGui::TableHeadersRow();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const TradeoffRow& row = rows[i];
    ImGui::PushID(static_cast<int>(i));
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(row.setting.c_str());
    ImGui::TableNextColumn();
    ImGui::Text(row.time_ms < 10.0 ? "%.2f" : "%.0f", row.time_ms);
    ImGui::TableNextColumn();
    ImGui::Text("%.4f", row.error.rmse);
    ImGui::TableNextColumn();
    if (std::isinf(row.error.psnr_db)) {
      ImGui::TextUnformatted("inf");
    } else {
      ImGui::Text("%.1f", row.error.psnr_db);
    }
    ImGui::TableNextColumn();
    ImGui::Text("%.2f", row.error.pct_pixels_off);
    ImGui::TableNextColumn();
    // ref: the reference's own setting; base: the setting every other knob's rows use.
    const char* mark = row.reference_setting && row.base_setting ? "ref, base"
                       : row.reference_setting                   ? "ref"
                       : row.base_setting                        ? "base"
                                                                 : "";
    ImGui::TextDisabled("%s", mark);
    ImGui::TableNextColumn();
    draw_use(commands, view, row);
    ImGui::PopID();
  }
  ImGui::EndTable();
}

void draw_knobs(const QualityMeasurement& q, Commands& commands, ViewSettings& view) {
  const std::optional<Knob> current = q.current_knob();
  for (const Knob knob : q.knobs()) {
    const std::vector<TradeoffRow> rows = rows_of_knob(q.rows(), knob);
    ImGui::Spacing();
    ImGui::TextUnformatted(to_string(knob));
    ImGui::SameLine(ImGui::CalcTextSize("tessellation  ").x);
    if (rows.empty()) {
      ImGui::TextDisabled(knob == current ? "measuring..." : q.running() ? "waiting" : "-");
      continue;
    }
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", quality_verdict(rows).c_str());
    ImGui::PopTextWrapPos();
    draw_knob_table(commands, view, knob, rows);
  }
}

// The ray tracer's knobs: Measure, the rows per knob with their verdicts, the notes.
void draw_cpu_tab(QualityMeasurement& q, Commands& commands, ViewSettings& view) {
  draw_controls(q, commands);
  if (q.state() == QualityMeasurement::State::idle) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled(
        "Measure renders the scene on screen under each setting of each accuracy knob and "
        "compares it with a reference. Times are for the measurement's small image; compare "
        "them with each other, not with the viewport's.");
    ImGui::PopTextWrapPos();
  } else {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled(
        "ref: the reference's setting; base: the setting all other rows use. Verdict: the "
        "cheapest setting within 1/255 on 99%% of pixels, else the cheapest 5%% faster than "
        "ref and as good (+1 point off, 1.5x RMSE at most).");
    ImGui::PopTextWrapPos();
  }
  draw_knobs(q, commands, view);
  if (!q.notes().empty()) {
    section_title("Notes");
    ImGui::PushTextWrapPos(0.0f);
    for (const std::string& note : q.notes()) ImGui::TextDisabled("%s", note.c_str());
    ImGui::PopTextWrapPos();
  }
}

}  // namespace

void draw_quality_panel(QualityState& quality, OpenWindows& windows, ViewSettings& view,
                        Commands& commands, ImVec2 pos, ImVec2 size) {
  if (!windows.quality) return;
  ImGui::SetNextWindowPos(pos, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(size, ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Quality: what each knob costs and buys", &windows.quality)) {
    ImGui::End();
    return;
  }
  // Three tabs: the ray tracer's knobs (the CPU rows), the raster path's rows (issue 12) and the
  // plot of both. Starting a raster measurement (button or script) shows its tab.
  if (!ImGui::BeginTabBar("quality tabs")) {
    ImGui::End();
    return;
  }
  if (ImGui::BeginTabItem("Ray tracer")) {
    draw_cpu_tab(quality.cpu, commands, view);
    ImGui::EndTabItem();
  }
  const ImGuiTabItemFlags raster_flags =
      quality.show_raster_rows ? ImGuiTabItemFlags_SetSelected : ImGuiTabItemFlags_None;
  if (ImGui::BeginTabItem("Raster (GLSL)", nullptr, raster_flags)) {
    quality.show_raster_rows = false;  // shown (a new tab bar selects its first tab at first)
    draw_raster_quality_section(quality, windows, commands);
    ImGui::EndTabItem();
  }
  if (ImGui::BeginTabItem("Plot")) {
    if (quality.cpu.rows().empty() && quality.raster.rows().empty()) {
      ImGui::TextDisabled("measure the ray tracer's knobs or the raster rows first");
    } else {
      draw_quality_plot(quality, std::max(160.0f, ImGui::GetContentRegionAvail().y - 60.0f));
    }
    ImGui::EndTabItem();
  }
  ImGui::EndTabBar();
  ImGui::End();
}

}  // namespace gloss

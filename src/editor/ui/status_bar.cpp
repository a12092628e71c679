// The status bar: which renderer drew the shown frame, its progress and speed, the UI's own frame
// time, the measured delay from an edit to its image, and the newest message.
#include <cstdio>

#include <imgui.h>

#include "editor/ui/notices.h"
#include "editor/ui/panels/panels.h"
#include "editor/ui/parts/frame_loop.h"
#include "editor/ui/parts/session.h"
#include "editor/ui/viewport/viewport.h"

namespace gloss {

void draw_status_bar(const Viewport& viewport, const ViewSettings& view, const FrameTimes& times,
                     const Notices& notices, const Session& session, ImVec2 pos, ImVec2 size) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoNav |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus;
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8.0f, 3.0f));
  const bool open = ImGui::Begin("##status", nullptr, flags);
  ImGui::PopStyleVar();
  if (!open) {
    ImGui::End();
    return;
  }
  if (session.autosaver && !session.autosaver->failure().empty()) {
    // First, so no window width cuts it off; stays until a write succeeds.
    ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "%s |",
                       autosave_notice(*session.autosaver).c_str());
    ImGui::SameLine();
  }
  const RenderedFrame* frame = viewport.shown_frame();
  if (frame != nullptr && viewport.shown_raster_a()) {
    // One pass at one sample per pixel: its time is the whole frame's (raster_renderer.h).
    const FrameInfo& info = frame->info;
    ImGui::Text("raster (GLSL) | %dx%d | %.1f ms/frame", info.width, info.height, info.pass_ms);
  } else if (frame != nullptr) {
    const FrameInfo& info = frame->info;
    const double rays_per_s =
        info.pass_ms > 0.0 ? static_cast<double>(info.rays) / (info.pass_ms * 1e-3) : 0.0;
    char speed[48];
    if (info.rays > 0) {
      std::snprintf(speed, sizeof speed, "%.2f Mrays/s", rays_per_s * 1e-6);
    } else {
      std::snprintf(speed, sizeof speed, "re-shade, no rays");  // shade/exponent-class edits
    }
    ImGui::Text("ray traced | pass %d | %d/%d spp | %dx%d | %.1f ms/pass | %s | %s", info.pass,
                info.spp, info.target_spp, info.width, info.height, info.pass_ms, speed,
                info.converged ? "converged" : "rendering");
  } else {
    ImGui::TextUnformatted("waiting for the first frame");
  }
  // In the A/B view the B side may come from the other renderer (ab_compare.h).
  const RenderedFrame* b = viewport.shown_frame_b();
  if (view.mode == ViewMode::ab && b != nullptr &&
      viewport.shown_raster_b() != viewport.shown_raster_a()) {
    ImGui::SameLine();
    if (viewport.shown_raster_b()) {
      ImGui::Text("| B: raster (GLSL) %.1f ms/frame", b->info.pass_ms);
    } else {
      ImGui::Text("| B: ray traced %d/%d spp", b->info.spp, b->info.target_spp);
    }
  }
  if (view.renderer == RendererChoice::automatic) {
    // Which renderer draws the next drag, and the measured frame times behind the choice.
    const Viewport::AutomaticReport r = viewport.automatic_report();
    ImGui::SameLine();
    const char* who = r.raster ? "raster" : "ray traced";
    if (r.raster_ms < 0.0) {
      ImGui::TextDisabled("| auto: drags raster (timing it)");
    } else if (r.ray_traced_ms >= 0.0) {
      ImGui::TextDisabled("| auto: drags %s (image after %.0f ms raster, %.0f ms ray traced)", who,
                          r.raster_ms, r.ray_traced_ms);
    } else if (r.ray_traced_pass_ms >= 0.0) {
      ImGui::TextDisabled("| auto: drags %s (image after %.0f ms raster, ray traced >= %.0f ms%s)",
                          who, r.raster_ms, r.ray_traced_pass_ms, r.raster ? "" : ": timing it");
    } else {
      ImGui::TextDisabled("| auto: drags %s (image after %.0f ms raster)", who, r.raster_ms);
    }
  }
  ImGui::SameLine();
  const LatencyProbe& latency = viewport.latency();
  ImGui::TextDisabled("| UI %.1f ms (max %.1f) | edit->image %.0f ms, full res %.0f ms",
                      times.average(), times.largest(), latency.first_image_ms,
                      latency.full_image_ms);
  if (!notices.last.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("| %s", notices.last.c_str());
  }
  ImGui::End();
}

}  // namespace gloss

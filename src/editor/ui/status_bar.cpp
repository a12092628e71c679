// The status bar: which renderer drew the shown frame, its progress and speed, the UI's own frame
// time, the measured delay from an edit to its image, and the newest message. At any window width
// the delays stay on screen: the renderer's part drops its details first, and a long message (or
// an autosave failure's reason) is cut in the middle (text_fit.h), whole in its tooltip.
#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "editor/model/layout/text_fit.h"
#include "editor/ui/notices.h"
#include "editor/ui/panels/panels.h"
#include "editor/ui/parts/frame_loop.h"
#include "editor/ui/parts/session.h"
#include "editor/ui/viewport/viewport.h"

namespace gloss {

namespace {

std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* pattern, ...) {
  char text[512];
  va_list args;
  va_start(args, pattern);
  std::vsnprintf(text, sizeof text, pattern, args);
  va_end(args);
  return text;
}

float text_width(const std::string& text) {
  return ImGui::CalcTextSize(text.c_str()).x;
}

// The renderer's part: in full, and short (what the shown frame is and how far it got).
void renderer_texts(const Viewport& viewport, const ViewSettings& view, std::string& full,
                    std::string& brief) {
  const RenderedFrame* frame = viewport.shown_frame();
  if (frame != nullptr && viewport.shown_raster_a()) {
    // One pass at one sample per pixel: its time is the whole frame's (raster_renderer.h).
    const FrameInfo& info = frame->info;
    full = format("raster (GLSL) | %dx%d | %.1f ms/frame", info.width, info.height, info.pass_ms);
    brief = format("raster (GLSL) | %.1f ms/frame", info.pass_ms);
  } else if (frame != nullptr) {
    const FrameInfo& info = frame->info;
    const double rays_per_s =
        info.pass_ms > 0.0 ? static_cast<double>(info.rays) / (info.pass_ms * 1e-3) : 0.0;
    // Shade and exponent edits re-shade without rays.
    const std::string speed =
        info.rays > 0 ? format("%.2f Mrays/s", rays_per_s * 1e-6) : "re-shade, no rays";
    const char* state = info.converged ? "converged" : "rendering";
    full = format("ray traced | pass %d | %d/%d spp | %dx%d | %.1f ms/pass | %s | %s", info.pass,
                  info.spp, info.target_spp, info.width, info.height, info.pass_ms, speed.c_str(),
                  state);
    brief = format("ray traced | %d/%d spp | %s", info.spp, info.target_spp, state);
    // The environment's exact path follows the samples, for minutes on a large image: say which
    // image is shown (the fast path has no shadows) and how far it got.
    if (info.env_target > 0) {
      const std::string environment =
          info.env_steps == 0
              ? format(" | environment: fast preview, 0/%d directions", info.env_target)
              : format(" | environment %d/%d directions", info.env_steps, info.env_target);
      full += environment;
      brief += environment;
    }
  } else {
    full = brief = "waiting for the first frame";
  }
  // In the A/B view the B side may come from the other renderer (ab_compare.h).
  const RenderedFrame* b = viewport.shown_frame_b();
  if (view.mode == ViewMode::ab && b != nullptr &&
      viewport.shown_raster_b() != viewport.shown_raster_a()) {
    full += viewport.shown_raster_b()
                ? format(" | B: raster (GLSL) %.1f ms/frame", b->info.pass_ms)
                : format(" | B: ray traced %d/%d spp", b->info.spp, b->info.target_spp);
  }
  if (view.renderer == RendererChoice::automatic) {
    // Which renderer draws the next drag, and the measured frame times behind the choice.
    const Viewport::AutomaticReport r = viewport.automatic_report();
    const char* who = r.raster ? "raster" : "ray traced";
    if (r.raster_ms < 0.0) {
      full += " | auto: drags raster (timing it)";
    } else if (r.ray_traced_ms >= 0.0) {
      full += format(" | auto: drags %s (image after %.0f ms raster, %.0f ms ray traced)", who,
                     r.raster_ms, r.ray_traced_ms);
    } else if (r.ray_traced_pass_ms >= 0.0) {
      full += format(" | auto: drags %s (image after %.0f ms raster, ray traced >= %.0f ms%s)", who,
                     r.raster_ms, r.ray_traced_pass_ms, r.raster ? "" : ": timing it");
    } else {
      full += format(" | auto: drags %s (image after %.0f ms raster)", who, r.raster_ms);
    }
  }
}

// Text that may have been cut: its full form in a tooltip.
void text_with_tooltip(const std::string& shown, const std::string& full, const ImVec4* colour) {
  if (colour != nullptr) {
    ImGui::TextColored(*colour, "%s", shown.c_str());
  } else {
    ImGui::TextDisabled("%s", shown.c_str());
  }
  if (shown != full && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", full.c_str());
}

}  // namespace

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
  const float gap = ImGui::GetStyle().ItemSpacing.x;
  float room = ImGui::GetContentRegionAvail().x;
  // The delays are kept whole, then the autosave failure (its reason cut to fit), then the
  // renderer's part (short when the full one does not fit), then the message in what is left.
  const LatencyProbe& latency = viewport.latency();
  const std::string delays =
      format("| UI %.1f ms (max %.1f) | edit->image %.0f ms, full res %.0f ms", times.average(),
             times.largest(), latency.first_image_ms, latency.full_image_ms);
  room -= text_width(delays) + gap;
  std::string autosave;
  if (session.autosaver && !session.autosaver->failure().empty()) {
    autosave = autosave_notice(*session.autosaver) + " |";
  }
  std::string full, brief;
  renderer_texts(viewport, view, full, brief);
  // An autosave failure and a message each keep at least the start of their text (240 pixels)
  // beside the renderer's part, which is short when the full one would not leave that.
  const std::string message = notices.last.empty() ? "" : "| " + notices.last;
  float others = 0.0f;
  for (const std::string* t : {static_cast<const std::string*>(&autosave), &message}) {
    if (!t->empty()) others += std::min(text_width(*t) + gap, 240.0f);
  }
  const std::string& renderer = text_width(full) + gap <= room - others ? full : brief;
  room -= text_width(renderer) + gap;
  if (!autosave.empty()) {
    // First, so no window width hides it; stays until a write succeeds.
    const ImVec4 red(1.0f, 0.35f, 0.3f, 1.0f);
    const std::string shown = fit_text(autosave, std::max(room, 120.0f), text_width);
    room -= text_width(shown) + gap;
    text_with_tooltip(shown, autosave, &red);
    ImGui::SameLine();
  }
  ImGui::TextUnformatted(renderer.c_str());
  if (renderer != full && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", full.c_str());
  ImGui::SameLine();
  ImGui::TextDisabled("%s", delays.c_str());
  if (!message.empty() && room > 0.0f) {
    const std::string shown = fit_text(message, room, text_width);
    if (!shown.empty()) {
      ImGui::SameLine();
      text_with_tooltip(shown, message, nullptr);
    }
  }
  ImGui::End();
}

}  // namespace gloss

#include "editor/ui/script_player.h"

#include <cstdio>

#include "base/error.h"
#include "base/overloaded.h"
#include "editor/model/quality_measurement.h"
#include "editor/ui/app.h"

namespace gloss {

namespace {}  // namespace

std::string stats_text(const App& app) {
  char text[512];
  const LatencyProbe& latency = app.viewport.latency();
  const RenderedFrame* frame = app.viewport.shown_frame();
  const FrameInfo info = frame != nullptr ? frame->info : FrameInfo{};
  const double rays_per_s =
      info.pass_ms > 0.0 ? static_cast<double>(info.rays) / (info.pass_ms * 1e-3) : 0.0;
  std::snprintf(text, sizeof text,
                "ui_frame_ms avg=%.2f max=%.2f frames=%d | edit_to_first_image_ms=%.1f "
                "edit_to_full_image_ms=%.1f | pass=%d spp=%d/%d size=%dx%d pass_ms=%.1f "
                "since_change_ms=%.1f rays_per_s=%.3g",
                app.frame_times.average(), app.frame_times.largest(), app.frame_times.size,
                latency.first_image_ms, latency.full_image_ms, info.pass, info.spp, info.target_spp,
                info.width, info.height, info.pass_ms, info.since_change_ms, rays_per_s);
  return text;
}

void ScriptPlayer::fail(App& app, const std::string& message, int status) {
  std::fprintf(stderr, "error: %s\n", message.c_str());
  app.exit_code = status;
  app.quit = true;
  m_next = m_script.lines.size();
}

bool ScriptPlayer::wait_done(App& app, double now_s) {
  switch (m_waiting) {
    case Waiting::converge:
      if (app.viewport.converged_and_shown(app.commands.revision(), app.view)) {
        m_waiting = Waiting::shown;  // one more frame, so a window capture shows it
        return false;
      }
      if (now_s > m_deadline_s) {
        const ScriptLine& line = m_script.lines[m_next];
        fail(app,
             m_script.file + ":" + std::to_string(line.line) +
                 ": the render did not converge in time",
             1);
      }
      return false;
    case Waiting::shown:
      return true;
    case Waiting::files:
      return app.exports.empty() && !app.capture.requested;
    case Waiting::sleep:
      return now_s >= m_deadline_s;
    case Waiting::quality: {
      if (app.quality.running()) return false;
      const ScriptLine& line = m_script.lines[m_next];
      const std::string where = m_script.file + ":" + std::to_string(line.line) + ": ";
      if (app.quality.state() == QualityMeasurement::State::failed) {
        fail(app, where + "quality measurement failed: " + app.quality.error(), 1);
        return false;
      }
      std::printf("quality: %zu rows, %d of %zu knobs, %dx%d, %.2f s\n", app.quality.rows().size(),
                  app.quality.knobs_done(), app.quality.knobs().size(), app.quality.width(),
                  app.quality.height(), app.quality.elapsed_s());
      std::fflush(stdout);
      return true;
    }
    case Waiting::none:
      return true;
  }
  return true;
}

void ScriptPlayer::run_quality(App& app, const QualityAction& action, const std::string& where,
                               bool& hold) {
  switch (action.verb) {
    case QualityAction::Verb::measure:
    case QualityAction::Verb::start:
      app.quality.start(app.commands.scene());
      app.show_quality = true;
      if (action.verb == QualityAction::Verb::measure) {
        m_waiting = Waiting::quality;
        hold = true;
      }
      return;
    case QualityAction::Verb::cancel:
      app.quality.cancel();
      return;
    case QualityAction::Verb::csv:
      try {
        write_quality_csv(action.path, app.quality.rows());
        std::printf("saved %s\n",
                    std::filesystem::absolute(action.path).lexically_normal().string().c_str());
        std::fflush(stdout);
      } catch (const std::exception& e) {
        fail(app, where + e.what(), 1);
      }
      return;
  }
}

void ScriptPlayer::step(App& app) {
  const double now = app.now_s();
  while (m_next < m_script.lines.size() && !app.quit) {
    if (m_waiting != Waiting::none) {
      if (!wait_done(app, now)) return;
      m_waiting = Waiting::none;
      ++m_next;
      continue;
    }
    const ScriptLine& line = m_script.lines[m_next];
    try {
      if (run_document_line(line, app.commands, m_script.file)) {
        ++m_next;
        continue;
      }
    } catch (const InputError& e) {
      fail(app, e.what(), 2);
      return;
    }
    const std::string where = m_script.file + ":" + std::to_string(line.line) + ": ";
    bool hold = false;
    std::visit(Overloaded{
                   [&](const WaitAction& a) {
                     m_waiting = Waiting::converge;
                     m_deadline_s = now + a.timeout_s;
                     hold = true;
                   },
                   [&](const ScreenshotAction& a) {
                     start_screenshot(app, a.kind, a.path, true);
                     m_waiting = Waiting::files;
                     hold = true;
                   },
                   [&](const ViewAction& a) {
                     app.view.mode = a.mode;
                     if (a.mode == ViewMode::single) app.view.single = a.term;
                   },
                   [&](const ExposureAction& a) { app.view.exposure = a.stops; },
                   [&](const EncodingAction& a) { app.view.srgb = a.srgb; },
                   [&](const SelectAction& a) {
                     if (a.object >= static_cast<int>(app.commands.scene().objects.size())) {
                       fail(app, where + "no object " + std::to_string(a.object), 2);
                       return;
                     }
                     app.selected_object = a.object;
                   },
                   [&](const StatsAction&) {
                     std::printf("stats: %s\n", stats_text(app).c_str());
                     std::fflush(stdout);
                     app.frame_times = FrameTimes{};
                   },
                   [&](const SleepAction& a) {
                     m_waiting = Waiting::sleep;
                     m_deadline_s = now + a.seconds;
                     hold = true;
                   },
                   [&](const AnimateAction& a) { app.view.orbit_light = a.on; },
                   [&](const QuitAction&) { app.quit = true; },
                   [&](const QualityAction& a) { run_quality(app, a, where, hold); },
                   [&](const auto&) {},  // document lines ran above
               },
               line.action);
    if (hold) return;
    if (!app.quit || app.exit_code == 0) ++m_next;
  }
}

}  // namespace gloss

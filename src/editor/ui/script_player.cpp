#include "editor/ui/script_player.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "base/atomic_file.h"
#include "base/error.h"
#include "editor/model/measure/memory_report.h"
#include "editor/model/measure/quality_measurement.h"
#include "editor/model/session/file_defaults.h"
#include "editor/model/script/script_runner.h"
#include "editor/ui/app.h"
#include "editor/ui/panels/quality_parts.h"
#include "editor/ui/shortcuts.h"

namespace gloss {

std::string layout_text(const App& app) {
  const PanelLayout& l = app.layout.last;
  const PanelChoices& c = app.layout.panels;
  std::string out;
  char line[256];
  auto rect = [&](const char* name, const LayoutRect& r) {
    std::snprintf(line, sizeof line, " %s=%g,%g,%gx%g", name, r.x, r.y, r.w, r.h);
    out += line;
  };
  std::snprintf(line, sizeof line, "layout: window=%gx%g", l.status.w, l.status.bottom());
  out += line;
  rect("viewport", l.viewport);
  rect("left", l.left);
  rect("outliner", l.outliner);
  rect("lights", l.lights);
  rect("view", l.view);
  rect("left_strip", l.left_strip);
  rect("right_strip", l.right_strip);
  rect("left_split", l.left_split);
  rect("right_split", l.right_split);
  rect("status", l.status);
  std::snprintf(line, sizeof line, " maximised=%d left_collapsed=%d right_collapsed=%d\n",
                c.viewport_maximised ? 1 : 0, c.left_collapsed ? 1 : 0, c.right_collapsed ? 1 : 0);
  out += line;
  const Viewport& v = app.viewport;
  std::snprintf(line, sizeof line, "layout: mode=%s panes=%d", to_string(app.view.mode),
                v.pane_count());
  out += line;
  const ImGuiViewport* main = ImGui::GetMainViewport();
  for (int i = 0; i < v.pane_count(); ++i) {
    const Pane& p = v.pane(i);
    const std::string name = "pane" + std::to_string(i);
    rect(name.c_str(), {p.min.x - main->Pos.x, p.min.y - main->Pos.y, p.size.x, p.size.y});
  }
  const Pane& g = v.legend();
  rect("legend", {g.min.x - main->Pos.x, g.min.y - main->Pos.y, g.size.x, g.size.y});
  out += "\n";
  // Each light's marker in the first pane, as fractions of it (what `mouse press` takes).
  const Scene& scene = app.document.scene();
  for (int i = 0; i < static_cast<int>(scene.lights.size()) && v.pane_count() > 0; ++i) {
    const Pane& p = v.pane(0);
    const EdgeMarker m = v.light_marker(scene, i, p);
    const glm::vec3& at = scene.lights[static_cast<std::size_t>(i)].position;
    std::snprintf(line, sizeof line,
                  "layout: light %d marker=%.4f,%.4f on_screen=%d selected=%d position=%g %g %g\n",
                  i, m.position.x / std::max(p.size.x, 1.0f),
                  m.position.y / std::max(p.size.y, 1.0f), m.on_screen ? 1 : 0,
                  i == app.selection.light ? 1 : 0, at.x, at.y, at.z);
    out += line;
  }
  return out;
}

std::string stats_text(App& app) {
  // Every pixel of the live image as shown (exposure_histogram.h: any channel above 1).
  const double clipped_share =
      app.viewport.histogram(app.view, display_transform(app.document.scene().render), true)
          .clipped_share();
  char text[512];
  const LatencyProbe& latency = app.viewport.latency();
  const RenderedFrame* frame = app.viewport.shown_frame();
  const FrameInfo info = frame != nullptr ? frame->info : FrameInfo{};
  const double rays_per_s =
      info.pass_ms > 0.0 ? static_cast<double>(info.rays) / (info.pass_ms * 1e-3) : 0.0;
  std::snprintf(text, sizeof text,
                "ui_frame_ms avg=%.2f median=%.2f max=%.2f frames=%d | edit_to_first_image_ms=%.1f "
                "edit_to_full_image_ms=%.1f | pass=%d spp=%d/%d size=%dx%d pass_ms=%.1f "
                "since_change_ms=%.1f rays_per_s=%.3g clipped=%.3g%%",
                app.frame.times.average(), app.frame.times.median(), app.frame.times.largest(),
                app.frame.times.size, latency.first_image_ms, latency.full_image_ms, info.pass,
                info.spp, info.target_spp, info.width, info.height, info.pass_ms,
                info.since_change_ms, rays_per_s, 100.0 * clipped_share);
  // Which renderer drew the shown frame (issue 12); in the A/B view both sides and the largest
  // difference the heat map scales to.
  std::string line = text;
  line += app.viewport.shown_raster_a() ? " renderer=gl" : " renderer=cpu";
  if (app.view.renderer == RendererChoice::automatic) {
    const Viewport::AutomaticReport r = app.viewport.automatic_report();
    std::snprintf(text, sizeof text,
                  " auto_drag=%s auto_raster_ms=%.2f auto_ray_traced_ms=%.2f "
                  "auto_ray_traced_pass_ms=%.2f",
                  r.raster ? "gl" : "cpu", r.raster_ms, r.ray_traced_ms, r.ray_traced_pass_ms);
    line += text;
  }
  if (app.view.mode == ViewMode::ab) {
    std::snprintf(text, sizeof text, " b_renderer=%s ab_max_difference=%.4g",
                  app.viewport.shown_raster_b() ? "gl" : "cpu", app.viewport.max_difference());
    line += text;
  }
  // New images on screen since the last `stats` and the delay of the edits they showed
  // (image_cadence.h): what continuous edits (an animation, a drag) look like.
  const ImageCadence::Window w = app.viewport.cadence().window(app.now_s());
  std::snprintf(text, sizeof text,
                " | window_s=%.2f new_images=%d image_gap_ms max=%.1f median=%.1f | "
                "edit_delay_ms median=%.1f max=%.1f edits_shown=%d",
                w.seconds, w.images, w.max_gap_ms, w.median_gap_ms, w.median_delay_ms,
                w.max_delay_ms, w.delays);
  line += text;
  return line;
}

void ScriptPlayer::fail(App& app, const std::string& message, int status) {
  std::fprintf(stderr, "error: %s\n", message.c_str());
  app.run.exit_code = status;
  app.run.quit = true;
  m_next = m_script.lines.size();
}

bool ScriptPlayer::wait_done(App& app, double now_s) {
  switch (m_waiting) {
    case Waiting::converge:
      if (app.viewport.converged_and_shown(app.document.revision(), app.view)) {
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
      return !app.exports.running() && !app.exports.capture_requested();
    case Waiting::sleep:
      return now_s >= m_deadline_s;
    case Waiting::quality: {
      const QualityMeasurement& quality = app.quality.cpu;
      if (quality.running()) return false;
      const ScriptLine& line = m_script.lines[m_next];
      const std::string where = m_script.file + ":" + std::to_string(line.line) + ": ";
      if (quality.state() == QualityMeasurement::State::failed) {
        fail(app, where + "quality measurement failed: " + quality.error(), 1);
        return false;
      }
      std::printf("quality: %zu rows, %d of %zu knobs, %dx%d, %.2f s\n", quality.rows().size(),
                  quality.knobs_done(), quality.knobs().size(), quality.width(), quality.height(),
                  quality.elapsed_s());
      std::fflush(stdout);
      return true;
    }
    case Waiting::layout:  // a frame has been laid out since the line: print that one
      std::printf("%s", layout_text(app).c_str());
      std::fflush(stdout);
      return true;
    case Waiting::none:
      return true;
  }
  return true;
}

// The editor's side of a script (script_runner.h): waits become the player's waiting states.
class ScriptPlayer::Host : public ScriptHost {
 public:
  Host(ScriptPlayer& player, App& app, double now_s) : m_player(player), m_app(app), m_now(now_s) {}

  CommandLayer& layer() override { return m_app.document; }
  ViewSettings& view() override { return m_app.view; }
  void select(int object) override { select_only(m_app.selection, object); }
  void select_objects(const std::vector<int>& objects) override {
    select_all_of(m_app.selection, objects);
  }
  int selected_object() const override { return m_app.selection.object; }
  std::optional<Snapshot>& snapshot() override { return m_app.snapshot; }
  void notify(const std::string& text) override { m_app.commands.info(text); }

  LineResult wait(const WaitAction& a, const std::string&) override {
    return hold(Waiting::converge, m_now + a.timeout_s);
  }
  LineResult screenshot(const ScreenshotAction& a, const std::string&) override {
    m_app.exports.start(a.kind, a.path, true);
    return hold(Waiting::files, 0.0);
  }
  LineResult stats() override {
    std::printf("stats: %s\n", stats_text(m_app).c_str());
    std::fflush(stdout);
    m_app.frame.times = FrameTimes{};
    m_app.viewport.restart_cadence(m_app.now_s());
    return LineResult::go_on();
  }
  LineResult memory() override {
    const ViewMemory view{
        m_app.viewport.frame_bytes(), m_app.viewport.texture_bytes(),
        m_app.library.swatches.texture_bytes() + m_app.library.balls.texture_bytes()};
    std::printf("memory: %s\n", memory_text(m_app.document, view).c_str());
    std::fflush(stdout);
    return LineResult::go_on();
  }
  LineResult save(const SaveAction& a, const std::string& where) override {
    try {
      m_app.files.save_scene_as(a.path);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "error: %s%s\n", where.c_str(), e.what());
      return LineResult::stop(1);
    }
    std::printf("saved scene %s\n", a.path.c_str());
    std::fflush(stdout);
    return LineResult::go_on();
  }
  // Opens the file panel as the File menu does, so a window screenshot shows it.
  LineResult browse(const BrowseAction& a) override {
    const std::pair<const char*, BrowsePurpose> kinds[] = {
        {"save-scene", BrowsePurpose::save_scene},
        {"save-material", BrowsePurpose::save_material},
        {"save-materials", BrowsePurpose::save_materials},
        {"export-glsl", BrowsePurpose::export_glsl},
        {"open-scene", BrowsePurpose::open_scene},
        {"add-model", BrowsePurpose::add_model}};
    FileBrowser& browser = m_app.session.browser;
    const Scene& scene = m_app.document.scene();
    for (const auto& [word, purpose] : kinds) {
      if (a.what == word) {
        browser.start(purpose, scene.path,
                      suggested_file_name(scene, m_app.selection.object, word));
      }
    }
    std::printf("browse: %s | %s\n", browser.folder.string().c_str(), browser.name.c_str());
    std::fflush(stdout);
    return LineResult::go_on();
  }
  LineResult mouse(const MouseAction& a) override {
    ScriptMouse& m = m_app.input.script_mouse;
    m.active = true;
    if (a.verb == MouseAction::Verb::release) {
      m.down = false;
    } else {
      m.x = a.x;
      m.y = a.y;
      if (a.verb == MouseAction::Verb::press) {
        m.down = true;
        m.button = a.button;
      }
    }
    return hold(Waiting::sleep, m_now);  // the next frame sees it
  }
  LineResult sleep(const SleepAction& a) override {
    return hold(Waiting::sleep, m_now + a.seconds);
  }
  LineResult layout(const LayoutAction& a, const std::string&) override {
    PanelChoices& p = m_app.layout.panels;
    switch (a.verb) {
      case LayoutAction::Verb::print:
        return hold(Waiting::layout, m_now);
      case LayoutAction::Verb::maximise:
        p.viewport_maximised = a.on;
        break;
      case LayoutAction::Verb::collapse:
      case LayoutAction::Verb::expand:
        (a.right ? p.right_collapsed : p.left_collapsed) = a.verb == LayoutAction::Verb::collapse;
        p.viewport_maximised = false;
        break;
      case LayoutAction::Verb::reset:
        p = PanelChoices{};
        break;
    }
    return hold(Waiting::sleep, m_now);  // the next frame is laid out with it
  }
  LineResult key(const KeyAction& a, const std::string& where) override {
    const Shortcut* shortcut = find_shortcut(a.keys);
    if (shortcut == nullptr) {
      std::fprintf(stderr, "error: %sno keyboard shortcut '%s' (the help window lists them)\n",
                   where.c_str(), a.keys.c_str());
      return LineResult::stop(2);
    }
    m_app.input.key_presses.push_back({shortcut->key, shortcut->mods, false});
    return hold(Waiting::sleep, m_now);  // the next frame acts on it
  }
  LineResult quality(const QualityAction& action, const std::string& where) override {
    switch (action.verb) {
      case QualityAction::Verb::measure:
      case QualityAction::Verb::start:
        m_app.quality.cpu.start(m_app.document.scene());
        m_app.windows.quality = true;
        if (action.verb == QualityAction::Verb::measure) return hold(Waiting::quality, 0.0);
        return LineResult::go_on();
      case QualityAction::Verb::cancel:
        m_app.quality.cpu.cancel();
        return LineResult::go_on();
      case QualityAction::Verb::raster:
        return quality_raster(action, where);
      case QualityAction::Verb::csv:
        try {
          write_quality_csv(action.path, m_app.quality.cpu.rows());
          std::printf("saved %s\n",
                      std::filesystem::absolute(action.path).lexically_normal().string().c_str());
          std::fflush(stdout);
          return LineResult::go_on();
        } catch (const std::exception& e) {
          std::fprintf(stderr, "error: %s%s\n", where.c_str(), e.what());
          return LineResult::stop(1);
        }
    }
    return LineResult::go_on();
  }

 private:
  // `quality raster`: measured at once on this thread (it owns the GL context), the UI paused
  // meanwhile; the rows stay in the Quality window.
  LineResult quality_raster(const QualityAction& action, const std::string& where) {
    try {
      start_raster_quality(m_app.quality, m_app.windows, m_app.document.scene(), action.width,
                           action.height, action.reference_spp);
      RasterTradeoff& r = m_app.quality.raster;
      while (r.running()) {
        if (!r.step(1e12)) std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
      if (r.state() == RasterTradeoff::State::failed) {
        throw std::runtime_error("raster quality measurement failed: " + r.error());
      }
      std::printf("quality raster: %zu rows, %dx%d, reference %d spp, %d runs, %.2f s\n%s",
                  r.rows().size(), r.width(), r.height(), r.options().reference_spp,
                  r.options().runs, r.elapsed_s(), raster_tradeoff_table(r.rows()).c_str());
      write_text_atomically(action.path, raster_tradeoff_to_csv(r.rows()));
      std::printf("saved %s\n",
                  std::filesystem::absolute(action.path).lexically_normal().string().c_str());
      std::fflush(stdout);
      return LineResult::go_on();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "error: %s%s\n", where.c_str(), e.what());
      return LineResult::stop(1);
    }
  }

  LineResult hold(Waiting waiting, double deadline_s) {
    m_player.m_waiting = waiting;
    m_player.m_deadline_s = deadline_s;
    return LineResult::hold();
  }

  ScriptPlayer& m_player;
  App& m_app;
  double m_now;
};

void ScriptPlayer::step(App& app) {
  const double now = app.now_s();
  while (m_next < m_script.lines.size() && !app.run.quit) {
    if (m_waiting != Waiting::none) {
      if (!wait_done(app, now)) return;
      m_waiting = Waiting::none;
      ++m_next;
      continue;
    }
    Host host(*this, app, now);
    const LineResult result = run_script_line(m_script, m_script.lines[m_next], host);
    if (result.next == LineResult::Next::hold) return;
    if (result.next == LineResult::Next::stop) {
      app.run.exit_code = result.status;
      app.run.quit = true;
      m_next = result.status != 0 ? m_script.lines.size() : m_next + 1;
      return;
    }
    ++m_next;
  }
}

}  // namespace gloss

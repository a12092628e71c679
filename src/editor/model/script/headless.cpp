#include "editor/model/script/headless.h"

#include <cstdio>
#include <ctime>

#include "base/error.h"
#include "editor/model/document/command_layer.h"
#include "editor/model/export/export_image.h"
#include "editor/model/measure/quality_measurement.h"
#include "editor/model/script/script_runner.h"

namespace gloss {

namespace {

void say_no_display(const std::string& reason) {
  std::fprintf(stderr, "gloss: no display (%s); using the CPU renderer without a window\n",
               reason.c_str());
}

// A script without frames: `wait` returns at once (every export renders to convergence),
// viewport and term screenshots render with the CPU renderer (`renderer gl` included), a window
// screenshot is an error, a started quality measurement is measured to its end at once and cancel
// does nothing.
class HeadlessHost : public ScriptHost {
 public:
  explicit HeadlessHost(const Scene& scene) : m_layer(scene) {}

  CommandLayer& layer() override { return m_layer; }
  ViewSettings& view() override { return m_view; }
  // Kept only for `export glsl` without an object index, which exports the selected object's.
  void select(int object) override { m_selected = object; }
  int selected_object() const override { return m_selected; }

  LineResult wait(const WaitAction&, const std::string&) override { return LineResult::go_on(); }
  LineResult screenshot(const ScreenshotAction& a, const std::string& where) override {
    if (a.kind == ScreenshotKind::window)
      return failed(where, "a window screenshot needs a display");
    if (a.kind == ScreenshotKind::shown)
      return failed(where, "a shown screenshot needs a display (no viewport shows a frame)");
    try {
      const Scene& scene = m_layer.scene();
      // Without a window there is no GL: every renderer choice exports the ray tracer's image,
      // and the file says so.
      ViewSettings view = m_view;
      view.renderer = RendererChoice::cpu;
      const Image image = render_export(scene, view, a.kind);
      const std::filesystem::path written =
          a.kind == ScreenshotKind::exr
              ? write_exr_export(a.path, image)
              : write_export(a.path, image, scene.render.srgb, export_text(scene, view, a.kind));
      saved(written);
      return LineResult::go_on();
    } catch (const std::exception& e) {
      return failed(where, e.what());
    }
  }
  LineResult stats() override {
    std::printf("stats: no display, no frames\n");
    return LineResult::go_on();
  }
  LineResult sleep(const SleepAction&) override { return LineResult::go_on(); }
  LineResult quality(const QualityAction& action, const std::string& where) override {
    try {
      if (action.verb == QualityAction::Verb::raster) {
        return failed(where, "quality raster draws with OpenGL: it needs the editor's window");
      }
      if (action.verb == QualityAction::Verb::csv) {
        write_quality_csv(action.path, m_quality.rows());
        saved(action.path);
      } else if (action.verb != QualityAction::Verb::cancel) {
        m_quality.start(m_layer.scene());
        m_quality.wait();
        if (m_quality.state() == QualityMeasurement::State::failed) {
          throw std::runtime_error("quality measurement failed: " + m_quality.error());
        }
      }
      return LineResult::go_on();
    } catch (const std::exception& e) {
      return failed(where, e.what());
    }
  }

 private:
  static LineResult failed(const std::string& where, const std::string& message) {
    std::fprintf(stderr, "error: %s%s\n", where.c_str(), message.c_str());
    return LineResult::stop(1);
  }
  static void saved(const std::filesystem::path& path) {
    std::printf("saved %s\n", std::filesystem::absolute(path).lexically_normal().string().c_str());
  }

  CommandLayer m_layer;
  ViewSettings m_view;
  QualityMeasurement m_quality;
  int m_selected = 0;
};

}  // namespace

int render_without_display(const Scene& scene, const std::string& reason) {
  say_no_display(reason);
  try {
    const ViewSettings view;
    const Image image = render_export(scene, view, ScreenshotKind::viewport);
    const std::filesystem::path path =
        write_png_unique(".", "gloss", image, scene.render.srgb,
                         export_text(scene, view, ScreenshotKind::viewport), std::time(nullptr));
    std::printf("rendered %s (%dx%d, %d spp) to %s\n",
                scene.path.empty() ? "the built-in scene" : scene.path.c_str(), scene.render.width,
                scene.render.height, scene.render.spp,
                std::filesystem::absolute(path).lexically_normal().string().c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}

int run_script_without_display(const Scene& scene, const Script& script,
                               const std::string& reason) {
  say_no_display(reason);
  HeadlessHost host(scene);
  for (const ScriptLine& line : script.lines) {
    const LineResult result = run_script_line(script, line, host);
    std::fflush(stdout);
    if (result.next == LineResult::Next::stop) return result.status;
  }
  return 0;
}

}  // namespace gloss

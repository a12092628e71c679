#include "editor/model/headless.h"

#include <cstdio>
#include <ctime>

#include "base/error.h"
#include "base/overloaded.h"
#include "editor/model/command_layer.h"
#include "editor/model/export_image.h"
#include "editor/model/quality_measurement.h"

namespace gloss {

namespace {

void say_no_display(const std::string& reason) {
  std::fprintf(stderr, "gloss: no display (%s); using the core renderer without a window\n",
               reason.c_str());
}

// Runs a quality line without frames: a started measurement is measured to its end at once and
// cancel does nothing. Returns the exit status to stop with, or -1 to go on.
int quality_line(QualityMeasurement& quality, const QualityAction& action,
                 const CommandLayer& layer, const std::string& where) {
  try {
    if (action.verb == QualityAction::Verb::csv) {
      write_quality_csv(action.path, quality.rows());
      std::printf("saved %s\n",
                  std::filesystem::absolute(action.path).lexically_normal().string().c_str());
    } else if (action.verb != QualityAction::Verb::cancel) {
      quality.start(layer.scene());
      quality.wait();
      if (quality.state() == QualityMeasurement::State::failed) {
        throw std::runtime_error("quality measurement failed: " + quality.error());
      }
    }
    return -1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s%s\n", where.c_str(), e.what());
    return 1;
  }
}

}  // namespace

int render_without_display(const Scene& scene, const std::string& reason) {
  say_no_display(reason);
  try {
    const ViewSettings view;
    const Image image = render_export(scene, view, ScreenshotKind::viewport);
    const std::filesystem::path path =
        write_png_unique(".", "gloss", image, view.srgb,
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
  CommandLayer layer(scene);
  ViewSettings view;
  QualityMeasurement quality;
  for (const ScriptLine& line : script.lines) {
    const std::string where = script.file + ":" + std::to_string(line.line) + ": ";
    try {
      if (run_document_line(line, layer, script.file)) continue;
    } catch (const InputError& e) {
      std::fprintf(stderr, "error: %s\n", e.what());
      return 2;
    }
    int status = -1;
    std::visit(Overloaded{
                   [&](const ScreenshotAction& a) {
                     if (a.kind == ScreenshotKind::window) {
                       std::fprintf(stderr, "error: %sa window screenshot needs a display\n",
                                    where.c_str());
                       status = 1;
                       return;
                     }
                     try {
                       const Image image = render_export(layer.scene(), view, a.kind);
                       const std::filesystem::path written = write_export(
                           a.path, image, view.srgb, export_text(layer.scene(), view, a.kind));
                       std::printf(
                           "saved %s\n",
                           std::filesystem::absolute(written).lexically_normal().string().c_str());
                     } catch (const std::exception& e) {
                       std::fprintf(stderr, "error: %s%s\n", where.c_str(), e.what());
                       status = 1;
                     }
                   },
                   [&](const ViewAction& a) {
                     view.mode = a.mode;
                     if (a.mode == ViewMode::single) view.single = a.term;
                   },
                   [&](const ExposureAction& a) { view.exposure = a.stops; },
                   [&](const EncodingAction& a) { view.srgb = a.srgb; },
                   [&](const SelectAction& a) {
                     if (a.object >= static_cast<int>(layer.scene().objects.size())) {
                       std::fprintf(stderr, "error: %sno object %d\n", where.c_str(), a.object);
                       status = 2;
                     }
                   },
                   [&](const StatsAction&) { std::printf("stats: no display, no frames\n"); },
                   [&](const QuitAction&) { status = 0; },
                   [&](const QualityAction& a) { status = quality_line(quality, a, layer, where); },
                   [&](const SleepAction&) {},    // no frames to let run
                   [&](const AnimateAction&) {},  // no animation without frames
                   [&](const auto&) {},  // wait: every export above rendered to convergence
               },
               line.action);
    std::fflush(stdout);
    if (status >= 0) return status;
  }
  return 0;
}

}  // namespace gloss

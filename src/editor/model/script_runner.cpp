#include "editor/model/script_runner.h"

#include <cstdio>
#include <cstdlib>

#include "base/overloaded.h"

namespace gloss {

namespace {

LineResult bad_line(const std::string& where, const std::string& message) {
  std::fprintf(stderr, "error: %s%s\n", where.c_str(), message.c_str());
  return LineResult::stop(2);
}

}  // namespace

Snapshot take_snapshot(const CommandLayer& layer, const std::optional<Snapshot>& previous) {
  int number = 1;
  if (previous && previous->label.rfind("snapshot ", 0) == 0) {
    number = std::atoi(previous->label.c_str() + 9) + 1;
  }
  return Snapshot{layer.scene(), layer.revision(), "snapshot " + std::to_string(number)};
}

LineResult run_script_line(const Script& script, const ScriptLine& line, ScriptHost& host) {
  const std::string where = script.file + ":" + std::to_string(line.line) + ": ";
  try {
    return std::visit(
        Overloaded{
            [&](const Command& command) {
              host.layer().execute(command);
              host.layer().seal();
              return LineResult::go_on();
            },
            [&](const UndoAction&) {
              if (!host.layer().undo()) throw CommandError("nothing to undo");
              return LineResult::go_on();
            },
            [&](const RedoAction&) {
              if (!host.layer().redo()) throw CommandError("nothing to redo");
              return LineResult::go_on();
            },
            [&](const ViewAction& a) {
              if (a.mode == ViewMode::ab && a.ab_source == AbSource::snapshot && !host.snapshot()) {
                return bad_line(where,
                                "no snapshot to compare with: take one "
                                "with 'snapshot' first");
              }
              if (a.mode == ViewMode::ab) host.view().ab_source = a.ab_source;
              host.view().mode = a.mode;
              if (a.mode == ViewMode::single) host.view().single = a.term;
              return LineResult::go_on();
            },
            [&](const ExposureAction& a) {
              host.view().exposure = a.stops;
              return LineResult::go_on();
            },
            [&](const SelectAction& a) {
              if (a.object >= static_cast<int>(host.layer().scene().objects.size())) {
                return bad_line(where, "no object " + std::to_string(a.object));
              }
              host.select(a.object);
              return LineResult::go_on();
            },
            [&](const AnimateAction& a) {
              host.view().orbit_light = a.on;
              return LineResult::go_on();
            },
            [&](const QuitAction&) { return LineResult::stop(0); },
            [&](const ClippedOverlayAction& a) {
              host.view().show_clipped = a.on;
              return LineResult::go_on();
            },
            [&](const SnapshotAction&) {
              host.snapshot() = take_snapshot(host.layer(), host.snapshot());
              std::printf("snapshot: %s\n", host.snapshot()->label.c_str());
              return LineResult::go_on();
            },
            [&](const WaitAction& a) { return host.wait(a, where); },
            [&](const ScreenshotAction& a) { return host.screenshot(a, where); },
            [&](const StatsAction&) { return host.stats(); },
            [&](const SleepAction& a) { return host.sleep(a); },
            [&](const QualityAction& a) { return host.quality(a, where); },
        },
        line.action);
  } catch (const CommandError& e) {
    return bad_line(where, e.what());
  }
}

}  // namespace gloss

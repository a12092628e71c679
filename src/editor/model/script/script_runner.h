#pragma once
// The one dispatcher of script lines (script.h). A script runs in two places, the editor's
// frame loop (editor/ui/script_player.h) and a headless run without a display (headless.h);
// each is a ScriptHost that carries out what differs between them (waiting, screenshots,
// stats, sleeping, the quality measurement), and run_script_line does everything else the same
// way for both: commands, undo and redo, view settings, selection, animation, quit.
#include <string>

#include <optional>
#include <vector>

#include "editor/model/document/command_layer.h"
#include "editor/model/script/script.h"
#include "editor/model/view/ab_compare.h"
#include "editor/model/view/view_settings.h"

namespace gloss {

// What a line left to do.
struct LineResult {
  enum class Next {
    go_on,  // run the next line
    hold,   // the host resumes the script when the line's wait is over
    stop,   // end the script with status
  };
  Next next = Next::go_on;
  int status = 0;  // with stop: 0 quit, 1 a render or a write failed, 2 a bad line

  static LineResult go_on() { return {}; }
  static LineResult hold() { return {Next::hold, 0}; }
  static LineResult stop(int status) { return {Next::stop, status}; }
};

class ScriptHost {
 public:
  virtual ~ScriptHost() = default;

  virtual CommandLayer& layer() = 0;
  virtual ViewSettings& view() = 0;
  virtual void select(int object) = 0;
  // Selects these objects (what an `object add` line added); by default the first alone.
  virtual void select_objects(const std::vector<int>& objects) {
    if (!objects.empty()) select(objects.front());
  }
  // The object whose material `export glsl` writes when the line names none.
  virtual int selected_object() const { return 0; }

  // where: "FILE:LINE: " for messages. Errors are printed by the host, which returns stop.
  virtual LineResult wait(const WaitAction& action, const std::string& where) = 0;
  virtual LineResult screenshot(const ScreenshotAction& action, const std::string& where) = 0;
  virtual LineResult stats() = 0;
  virtual LineResult sleep(const SleepAction& action) = 0;
  virtual LineResult quality(const QualityAction& action, const std::string& where) = 0;
  // Prints the `memory` line (memory_report.h) on stdout; this default knows no window (frames,
  // textures and swatches read 0).
  virtual LineResult memory();
  // A viewport gesture (script.h, MouseAction); nothing without a display.
  virtual LineResult mouse(const MouseAction&) { return LineResult::go_on(); }
  // `save PATH`: saves the document there and makes it the document's file; the editor's host
  // goes through its file actions (recent files, the last folder).
  virtual LineResult save(const SaveAction& action, const std::string& where);
  // `browse WHAT`: prints where the file panel starts and what it suggests; this default has no
  // panel and no last folder (file_defaults.h's rules alone).
  virtual LineResult browse(const BrowseAction& action);
  // The window's layout and keyboard shortcuts (script.h, LayoutAction and KeyAction); without a
  // display these say so on stdout and go on.
  virtual LineResult layout(const LayoutAction& action, const std::string& where);
  virtual LineResult key(const KeyAction& action, const std::string& where);
  // A message for the user beside what the line prints (the editor's notices and status bar);
  // nothing without a window.
  virtual void notify(const std::string&) {}

  // The snapshot `snapshot` takes and `view ab snapshot` compares with. Kept here by default
  // (headless runs, tests); the editor keeps it in its App so the panel's button shares it.
  virtual std::optional<Snapshot>& snapshot() { return m_snapshot; }

 private:
  std::optional<Snapshot> m_snapshot;
};

// The snapshot of layer's document, numbered after previous (1 for the first).
Snapshot take_snapshot(const CommandLayer& layer, const std::optional<Snapshot>& previous);

// Runs one line of script on host. A failing line prints "error: FILE:LINE: ..." on stderr and
// returns stop with status 2 (bad line: a command that cannot apply, no such object, nothing to
// undo) or the host's status.
LineResult run_script_line(const Script& script, const ScriptLine& line, ScriptHost& host);

}  // namespace gloss

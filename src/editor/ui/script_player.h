#pragma once
// Plays a Script inside the running editor, a few lines per frame, through the one dispatcher
// (editor/model/script/script_runner.h): document lines go through the command layer at once;
// `wait`, `screenshot`, `sleep` and `quality measure` hold the script until the renderer has
// converged and its frame is on screen, the file is written, the time has passed or the measurement
// ended.
#include <cstddef>
#include <string>

#include "editor/model/script/script.h"

namespace gloss {

struct App;

class ScriptPlayer {
 public:
  explicit ScriptPlayer(Script script) : m_script(std::move(script)) {}

  // Runs lines until one must wait. On a failing line prints "error: FILE:LINE: ..." and makes
  // the editor quit with status 2 (bad line) or 1 (a render or a write failed).
  void step(App& app);
  bool finished() const { return m_next >= m_script.lines.size(); }

 private:
  enum class Waiting { none, converge, shown, files, sleep, quality, layout };
  class Host;
  friend class Host;
  bool wait_done(App& app, double now_s);
  void fail(App& app, const std::string& message, int status);

  Script m_script;
  std::size_t m_next = 0;
  Waiting m_waiting = Waiting::none;
  double m_deadline_s = 0.0;
};

// The `layout` line's text: where the panels, panes, legend and light markers are.
std::string layout_text(const App& app);
// The `stats` line's text: UI frame times, edit-to-image delays, the renderer's last pass.
std::string stats_text(App& app);  // non-const: computes the clipped share

}  // namespace gloss

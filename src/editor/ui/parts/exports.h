#pragma once
// Exports: screenshots of the viewport, the term sheet and the whole window, written on worker
// threads. A panel, the menu, a shortcut or a script starts one here; run_frame collects the
// finished ones and reads the back buffer for a window capture. Exports read the document (through
// the command door, which also shows their notices), the view settings and the viewport's raster
// path; they change none of them.
#include <filesystem>
#include <future>
#include <string>
#include <vector>

#include <GLFW/glfw3.h>

#include "editor/model/view/view_settings.h"

namespace gloss {

class Commands;
class Viewport;

// A viewport or term-sheet export rendering on a worker thread.
struct PendingExport {
  std::future<std::filesystem::path> path;  // the file written; throws what the export threw
  bool from_script = false;
};

// A window screenshot waits for the frame to be drawn: run_frame reads the back buffer.
struct WindowCapture {
  bool requested = false;
  std::string path;  // empty: a timestamped name in view.screenshot_dir
  bool from_script = false;
  // Frames to draw before reading: a request from a menu waits one frame, in which the closed
  // menu is no longer drawn (the frame of the click still shows it).
  int frames_to_skip = 0;
};

class Exports {
 public:
  Exports(Commands& commands, const ViewSettings& view, Viewport& viewport)
      : m_commands(commands), m_view(view), m_viewport(viewport) {}

  // Starts an export; path empty = timestamped name in view.screenshot_dir.
  void start(ScreenshotKind kind, const std::string& path = "", bool from_script = false);
  // Collects finished exports, showing their paths (or errors) as notices. Returns true when an
  // export a script started failed (the script then fails: exit status 1).
  bool poll();
  // After drawing, before the swap: reads the back buffer when a window capture is due.
  void capture_if_due(GLFWwindow* window);
  // Waits for every export still running, printing "saved PATH" or the error; false when one
  // failed (the editor is quitting).
  bool finish();

  bool capture_requested() const { return m_capture.requested; }
  bool running() const { return !m_pending.empty(); }

 private:
  void capture_window(GLFWwindow* window);

  Commands& m_commands;
  const ViewSettings& m_view;
  Viewport& m_viewport;
  std::vector<PendingExport> m_pending;
  WindowCapture m_capture;
};

}  // namespace gloss

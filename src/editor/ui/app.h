#pragma once
// The editor's state, grouped into parts by concern; App owns the parts and run_frame hands each
// panel only the parts it reads, plus the one door it writes through (a panel's signature in
// panels/panels.h says what it can touch). main.cpp creates one App after the GL context exists
// and calls run_frame until it quits.
//
// Where new state belongs:
// - the document (objects and their transforms, materials, lights, the environment, a reference
//   material): the Scene, changed only by Commands (editor/model/document/command.h) sent
//   through the door, parts/commands.h; a panel that edits it takes Commands&;
// - how the document is shown (view modes, overlays, what a view compares): ViewSettings
//   (editor/model/view/view_settings.h), so scripts and exports see it too;
// - what is selected (objects, lights): parts/selection.h;
// - a panel's own state between frames (an outliner's filter and open rows, a reference panel's
//   fit in progress, an environment panel's preview): panels/panel_state.h, one struct per
//   panel, handed to that panel alone; a viewport gesture's state (a gizmo drag) in Viewport;
// - where panels sit, their sizes and whether they are collapsed: parts/layout_state.h;
// - which floating windows and questions are open: parts/open_windows.h;
// - files, recent lists, autosave, recovery, a user library's folder: parts/session.h, with the
//   actions on them in parts/file_actions.h;
// - materials offered for applying (presets, loaded files, a user library's swatches):
//   parts/material_library.h;
// - exports (screenshots, files written in the background): parts/exports.h;
// - keyboard and mouse queues: parts/input_state.h;
// - the frame clock and the loop's bookkeeping: parts/frame_loop.h.
// A new panel: its function in panels/panels.h, taking only the parts it touches (an action it
// starts comes as that action's part: FileBrowser, Exports, FileActions), called from layout.cpp.
#include <optional>

#include <GLFW/glfw3.h>

#include "editor/model/document/command_layer.h"
#include "editor/model/view/ab_compare.h"
#include "editor/model/view/view_settings.h"
#include "editor/ui/notices.h"
#include "editor/ui/panels/panel_state.h"
#include "editor/ui/parts/commands.h"
#include "editor/ui/parts/exports.h"
#include "editor/ui/parts/file_actions.h"
#include "editor/ui/parts/frame_loop.h"
#include "editor/ui/parts/input_state.h"
#include "editor/ui/parts/layout_state.h"
#include "editor/ui/parts/material_library.h"
#include "editor/ui/parts/open_windows.h"
#include "editor/ui/parts/run_state.h"
#include "editor/ui/parts/selection.h"
#include "editor/ui/parts/session.h"
#include "editor/ui/viewport/viewport.h"

namespace gloss {

struct App {
  App(GLFWwindow* window, Scene scene);
  ~App();
  App(const App&) = delete;
  App& operator=(const App&) = delete;

  GLFWwindow* window;
  Clock clock;            // the frame clock: seconds since start (now_s)
  CommandLayer document;  // owns the document; panels change it only through `commands`
  Notices notices;        // messages over the viewport's corner, the newest in the status bar
  Commands commands{document, notices, clock};  // the door panels and the viewport write through
  ViewSettings view;                            // how the document is shown (not undone)
  Selection selection;
  std::optional<Snapshot> snapshot;  // the A side of the snapshot A/B (ab_compare.h)

  InputState input;
  LayoutState layout;
  OpenWindows windows;
  Session session;  // files and session
  MaterialLibrary library;

  Viewport viewport;
  MaterialPanelState material_panel;
  ReferencePanelState reference_panel;
  OutlinerState outliner;
  InspectorState inspector;
  QualityState quality;  // the Quality window's speed/accuracy measurements

  RunState run;  // the script, quitting, the exit status
  Exports exports{commands, view, viewport};
  FileActions files{document, commands, selection, session, library, windows, run};
  FrameLoop frame;

  double now_s() const { return clock.now_s(); }
};

// One frame: events already polled. Builds the UI, feeds the renderer, draws and swaps.
void run_frame(App& app);

// layout.cpp: the menu bar, the panels, the viewport and the windows at their places, each
// handed the parts it may touch (panels/panels.h).
void draw_layout(App& app);

// Seconds the event loop may sleep before the next frame (negative: do not sleep).
double idle_timeout(const App& app);

}  // namespace gloss

#pragma once
// The editor's state: the command layer (which owns the document), the view settings, the
// viewport and panels' state, and what runs in the background (exports, autosave, a script).
// main.cpp creates one App after the GL context exists and calls run_frame until it quits.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <GLFW/glfw3.h>
#include <glad/gl.h>

#include "editor/gl/raster_tradeoff.h"
#include "editor/model/document/command_layer.h"
#include "editor/model/measure/quality_measurement.h"
#include "editor/model/session/autosave.h"
#include "editor/model/session/background_priority.h"
#include "editor/model/session/recent_files.h"
#include "editor/model/session/unsaved_guard.h"
#include "editor/model/view/view_settings.h"
#include "editor/ui/file_browser.h"
#include "editor/ui/notices.h"
#include "editor/ui/panels/swatches.h"
#include "editor/ui/viewport/viewport.h"
#include "io/material/material_io.h"
#include "reference/pixel_inspection.h"

namespace gloss {

class ScriptPlayer;

// UI frame times (CPU time from the start of a frame to after its buffer swap), last 240.
struct FrameTimes {
  static constexpr int kCount = 240;
  double ms[kCount] = {};
  int size = 0, next = 0;
  void add(double value);
  double average() const;
  double median() const;  // the Speed targets are medians: one stall does not move it
  double largest() const;
};

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

// A key press (or auto-repeat) as GLFW reported it. Queued by a callback so that a press and
// release arriving between two frames still count: ImGui 1.86 only sees key state per frame.
struct KeyPress {
  int key = 0;   // GLFW_KEY_*
  int mods = 0;  // GLFW_MOD_* bits
  bool repeat = false;
};

// The pixel inspector's readers (inspector_panel.cpp) and the pixel under the cursor.
struct InspectorState {
  std::unique_ptr<PixelInspector> a, b;  // the document (A/B view: its Phong and Blinn sides)
  std::uint64_t revision = 0;            // document revision they were built for
  bool ab = false, keep = false;         // the A/B split and exponent rule they were built for
  AbSource source = AbSource::models;    // what the A/B compared (ab_compare.h)
  std::uint64_t snapshot = 0;            // the snapshot's revision + 1 they were built for, 0 none
  std::string error;                     // why they could not be built
  int hover_x = -1, hover_y = -1;        // render pixel under the cursor this frame, -1: none
};

struct App {
  App(GLFWwindow* window, Scene scene);
  ~App();

  GLFWwindow* window;
  CommandLayer commands;
  ViewSettings view;
  int selected_object = 0;
  int selected_light = 0;
  bool link_channels = false;  // material colour editors move R, G, B together
  // Side panels, dragged by the splitters at their inner edges (screen pixels; 0: the default
  // share of the window). lights_share: the Lights panel's part of the right column's height.
  float left_width = 0.0f, right_width = 0.0f, lights_share = 0.5f;

  Viewport viewport;
  Swatches swatches;
  QualityMeasurement quality;     // the Quality window's speed/accuracy measurement
  RasterTradeoff raster_quality;  // its raster (GLSL) rows, drawn on this thread (quality_parts.h)
  FileBrowser browser;
  Notices notices;
  RecentLists recent;    // scenes, models and material files, each its own list
  UnsavedGuard unsaved;  // the save / discard / cancel question before opening a scene
  std::filesystem::path config_folder;
  std::optional<Autosaver> autosaver;
  std::string autosave_failure_shown;        // the autosave failure already announced as a notice
  std::optional<Recovery> offered_recovery;  // a crashed session's document awaiting an answer
  std::unique_ptr<ScriptPlayer> script;
  std::optional<Snapshot> snapshot;    // the A side of the snapshot A/B (ab_compare.h)
  std::vector<NamedMaterial> library;  // materials loaded from a file, applied on demand
  std::string library_source;
  std::vector<PendingExport> exports;
  WindowCapture capture;
  std::vector<KeyPress> key_presses;  // since the last frame
  std::vector<int> key_taps;          // keys pressed and released since the last frame
  std::vector<int> taps_down;         // taps shown to ImGui as held during this frame
  ImVec2 cursor_position;             // the cursor as of the last event (window pixels)
  ImVec2 press_position[3];           // where each mouse button last went down (window pixels)
  // The mouse a script's `mouse` lines hold (script.h, MouseAction): once a script has used it,
  // it stands in for the real one. x, y: fractions of the viewport image.
  struct ScriptMouse {
    bool active = false, down = false;
    bool shown_down = false;  // what ImGui was last shown
    int button = 0;
    float x = 0.5f, y = 0.5f;
  };
  ScriptMouse script_mouse;
  FrameTimes frame_times;
  BackgroundPriority background;  // render and export threads below the UI (created on it)
  double background_checked_s = -1.0;
  InspectorState inspector;

  std::string title;                     // the window title last set
  double last_frame_s = 0.0;             // start of the previous frame (orbit-light animation step)
  std::uint64_t released_at_upload = 0;  // viewport.uploads() when free memory was last released
  bool show_help = false;
  bool show_about = false;
  bool show_quality = false;      // the Quality window
  bool show_raster_rows = false;  // select the Quality window's raster tab on its next frame
  bool confirm_quit = false;      // the unsaved-changes question is open
  bool quit = false;
  int exit_code = 0;

  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  double now_s() const;
};

// One frame: events already polled. Builds the UI, feeds the renderer, draws and swaps.
void run_frame(App& app);

// Seconds the event loop may sleep before the next frame (negative: do not sleep).
double idle_timeout(const App& app);

// The one door for panel and viewport edits: executes command, reporting a CommandError as a
// notice. Returns true when the document changed.
bool execute(App& app, const Command& command);

// app_actions.cpp: file and export actions. Each throws InputError / RuntimeFailure with a
// message for the UI; on failure the document is unchanged.
void open_scene(App& app, const std::string& path);
// Opens path, first asking save / discard / cancel when the document has unsaved changes (the
// question is a modal; scripts never ask). Throws as open_scene when it opens at once.
void request_open_scene(App& app, const std::string& path);
void add_model(App& app, const std::string& path);
void save_scene_as(App& app, const std::string& path);
void load_materials(App& app, const std::string& path);
void save_materials(App& app, const std::string& path);
// Writes the selected object's material as a GLSL fragment shader
// (editor/model/export/glsl_export.h).
void export_glsl_shader(App& app, const std::string& path);
// Starts an export; path empty = timestamped name in view.screenshot_dir.
void start_screenshot(App& app, ScreenshotKind kind, const std::string& path, bool from_script);
// Collects finished exports, showing their paths (or errors) as notices.
void poll_exports(App& app);
// Reads the back buffer and writes the requested window screenshot.
void capture_window(App& app);
// Runs the file browser's chosen action, keeping the browser open with the error on failure.
void browser_action(App& app, const std::string& path);
void remember_recent(App& app, RecentKind kind, const std::string& path);
void request_quit(App& app);
void undo(App& app);
void redo(App& app);
// Keeps the current document as the snapshot and shows the snapshot | live A/B view.
void snapshot_and_compare(App& app);

// shortcuts.cpp: install_input_callbacks before ImGui's GLFW backend (which chains to them),
// then handle_shortcuts once per frame.
void install_input_callbacks(GLFWwindow* window);
// Between the backend's NewFrame and ImGui::NewFrame: shows this frame's taps as held keys.
void replay_key_taps(App& app);
// Also there: a script's mouse (App::script_mouse) in place of the real one.
void replay_script_mouse(App& app);
void handle_shortcuts(App& app);
// Closes open menus, combo lists and other popups, but not a modal question (Esc, captures).
void close_menus();

// Panels (one file each).
void draw_menu_bar(App& app);
void draw_material_panel(App& app, ImVec2 pos, ImVec2 size);
void draw_lights_panel(App& app, ImVec2 pos, ImVec2 size);
void draw_view_panel(App& app, ImVec2 pos, ImVec2 size);
void draw_status_bar(App& app, ImVec2 pos, ImVec2 size);
void draw_help_window(App& app);
void draw_quality_panel(App& app, ImVec2 pos, ImVec2 size);
// The lobe view, drawn by the viewport in its place when view.mode is ViewMode::lobe.
void draw_lobe_view(App& app, ImVec2 pos, ImVec2 size);
// The pixel inspector window (view.show_inspector).
void draw_inspector(App& app, ImVec2 viewport_pos, ImVec2 viewport_size);

}  // namespace gloss

#pragma once
// Keyboard shortcuts and the input plumbing under them (shortcuts.cpp). install_input_callbacks
// before ImGui's GLFW backend (which chains to them), then each frame: replay_key_taps and
// replay_script_mouse between the backend's NewFrame and ImGui::NewFrame, handle_shortcuts after.
#include <string>
#include <vector>

#include <GLFW/glfw3.h>

namespace gloss {

struct App;
struct InputState;
class Viewport;

// The callbacks queue events into the InputState set as the window's user pointer.
void install_input_callbacks(GLFWwindow* window);
// Shows this frame's taps (keys pressed and released between two frames) as held keys.
void replay_key_taps(InputState& input, GLFWwindow* window);
// A script's mouse (InputState::script_mouse) in place of the real one.
void replay_script_mouse(InputState& input, const Viewport& viewport);
// What a key does. One table (shortcuts()) maps keys to these: handle_shortcuts dispatches from
// it and the help window lists it, so a key cannot work without being listed.
enum class ShortcutAction {
  help,
  undo,
  redo,
  screenshot,
  save_scene,
  open_scene,
  quit,
  snapshot,
  view_render,
  view_terms,
  view_single,
  view_ab,
  view_lobe,
  inspector,
  maximise_viewport,
  toggle_left_panel,
  toggle_right_panels,
  close,
  gizmo_move,  // the objects' keys (issue 24)
  gizmo_rotate,
  gizmo_scale,
  frame_selection,
  delete_objects,
  duplicate_objects,
  hide_objects,
  solo_objects,
  show_all_objects,
  rename_object,
};

struct Shortcut {
  int key = 0;   // GLFW_KEY_*
  int mods = 0;  // exactly these of Ctrl, Shift, Alt, Super
  ShortcutAction action = ShortcutAction::help;
  const char* keys = "";  // as the help window and docs/editor.md write it
  const char* what = "";  // what it does
  bool repeats = false;   // acts on auto-repeat too (undo, redo)
  bool plain = false;     // a key without modifiers: not while a widget is being edited
};
// Every keyboard shortcut, in the order the help window lists them (several keys may share an
// action and a line: the line is written once, on the first).
const std::vector<Shortcut>& shortcuts();

// A shortcut's keys as one name: "Ctrl+Shift+Z", "F1", "Ctrl+Space", "[".
std::string shortcut_name(const Shortcut& shortcut);
// The shortcut called keys (shortcut_name, any case), or null.
const Shortcut* find_shortcut(const std::string& keys);

// The shortcuts reach every part of the App, as the menus do (help_window.cpp lists them).
void handle_shortcuts(App& app);
// Closes open menus, combo lists and other popups, but not a modal question (Esc, captures).
void close_menus();

}  // namespace gloss

#pragma once
// Keyboard shortcuts and the input plumbing under them (shortcuts.cpp). install_input_callbacks
// before ImGui's GLFW backend (which chains to them), then each frame: replay_key_taps and
// replay_script_mouse between the backend's NewFrame and ImGui::NewFrame, handle_shortcuts after.
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
// The shortcuts reach every part of the App, as the menus do (help_window.cpp lists them).
void handle_shortcuts(App& app);
// Closes open menus, combo lists and other popups, but not a modal question (Esc, captures).
void close_menus();

}  // namespace gloss

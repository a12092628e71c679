#pragma once
// The input the editor queues between frames for its own use: GLFW key events for the shortcuts,
// the cursor and button presses as the events reported them, and the mouse a script holds.
// Written by the GLFW callbacks (shortcuts.cpp, which find it through the window's user pointer)
// and the script player; read by the shortcuts and the viewport's gestures.
#include <vector>

#include <imgui.h>

namespace gloss {

// A key press (or auto-repeat) as GLFW reported it. Queued by a callback so that a press and
// release arriving between two frames still count: ImGui 1.86 only sees key state per frame.
struct KeyPress {
  int key = 0;   // GLFW_KEY_*
  int mods = 0;  // GLFW_MOD_* bits
  bool repeat = false;
};

// The mouse a script's `mouse` lines hold (script.h, MouseAction): once a script has used it,
// it stands in for the real one. x, y: fractions of the viewport image.
struct ScriptMouse {
  bool active = false, down = false;
  bool shown_down = false;  // what ImGui was last shown
  int button = 0;
  float x = 0.5f, y = 0.5f;
};

struct InputState {
  std::vector<KeyPress> key_presses;  // since the last frame
  std::vector<int> key_taps;          // keys pressed and released since the last frame
  std::vector<int> taps_down;         // taps shown to ImGui as held during this frame
  ImVec2 cursor_position;             // the cursor as of the last event (window pixels)
  ImVec2 press_position[3];           // where each mouse button last went down (window pixels)
  ScriptMouse script_mouse;
};

}  // namespace gloss

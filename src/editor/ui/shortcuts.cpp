// Keyboard shortcuts (listed in the help window and docs/editor.md) and the input plumbing under
// them. Dear ImGui 1.86 reads key state once per frame, so a press and release that arrive
// between two frames would be lost: shortcuts read a queue of GLFW key events instead, and such
// taps are replayed to ImGui as held for one frame (Enter in a text field, Backspace ...).
#include <imgui.h>
#include <imgui_internal.h>

#include "editor/ui/shortcuts.h"

#include "editor/ui/app.h"
#include "editor/ui/panels/panels.h"

namespace gloss {

namespace {

// The cursor as of the event being handled (glfwGetCursorPos on X11 asks the server for the
// pointer now, which may be later motion).
void on_cursor(GLFWwindow* window, double x, double y) {
  auto* input = static_cast<InputState*>(glfwGetWindowUserPointer(window));
  if (input != nullptr)
    input->cursor_position = ImVec2(static_cast<float>(x), static_cast<float>(y));
}

// Where each mouse button went down: by the time ImGui's frame sees a press, later motion in
// the same batch of events has already moved io.MousePos.
void on_mouse_button(GLFWwindow* window, int button, int action, int /*mods*/) {
  auto* input = static_cast<InputState*>(glfwGetWindowUserPointer(window));
  if (input != nullptr && action == GLFW_PRESS && button >= 0 && button < 3) {
    input->press_position[button] = input->cursor_position;
  }
}

void on_key(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
  auto* input = static_cast<InputState*>(glfwGetWindowUserPointer(window));
  if (input == nullptr) return;
  if (action == GLFW_PRESS || action == GLFW_REPEAT) {
    input->key_presses.push_back({key, mods, action == GLFW_REPEAT});
  } else if (action == GLFW_RELEASE) {
    for (const KeyPress& press : input->key_presses) {
      if (press.key == key) {
        input->key_taps.push_back(key);
        break;
      }
    }
  }
}

void save_scene_shortcut(App& app) {
  const std::string& path = app.document.scene().path;
  if (path.empty()) {
    app.session.browser.show(BrowsePurpose::save_scene, app.view.screenshot_dir, "scene.json");
    return;
  }
  try {
    app.files.save_scene_as(path);
  } catch (const std::exception& e) {
    app.commands.error(e.what());
  }
}

}  // namespace

void close_menus() {
  // Dear ImGui 1.86 closes popups on Esc only with keyboard navigation on, which would also
  // move focus with the arrow keys; this closes them to the innermost modal instead.
  ImGuiContext& g = *ImGui::GetCurrentContext();
  int keep = 0;
  for (int i = 0; i < g.OpenPopupStack.Size; ++i) {
    const ImGuiWindow* w = g.OpenPopupStack[i].Window;
    if (w != nullptr && (w->Flags & ImGuiWindowFlags_Modal) != 0) keep = i + 1;
  }
  if (keep < g.OpenPopupStack.Size) ImGui::ClosePopupToLevel(keep, true);
}

void install_input_callbacks(GLFWwindow* window) {
  glfwSetKeyCallback(window, on_key);
  glfwSetMouseButtonCallback(window, on_mouse_button);
  glfwSetCursorPosCallback(window, on_cursor);  // ImGui 1.86's backend installs none
}

void replay_script_mouse(InputState& input, const Viewport& viewport) {
  ScriptMouse& m = input.script_mouse;
  if (!m.active) return;
  ImGuiIO& io = ImGui::GetIO();
  const ImVec2 p = viewport.image_point(m.x, m.y);
  if (m.down && !m.shown_down) input.press_position[m.button] = p;  // as on_mouse_button does
  io.MousePos = p;
  for (bool& down : io.MouseDown) down = false;
  io.MouseDown[m.button] = m.down;
  m.shown_down = m.down;
}

void replay_key_taps(InputState& input, GLFWwindow* window) {
  ImGuiIO& io = ImGui::GetIO();
  for (int key : input.taps_down) {
    if (glfwGetKey(window, key) == GLFW_RELEASE) io.KeysDown[key] = false;
  }
  input.taps_down.clear();
  for (int key : input.key_taps) {
    if (key >= 0 && key < IM_ARRAYSIZE(io.KeysDown)) {
      io.KeysDown[key] = true;
      input.taps_down.push_back(key);
    }
  }
  input.key_taps.clear();
  // The backend derives the modifiers from the key state in its callback; keep them in step.
  io.KeyCtrl = io.KeysDown[GLFW_KEY_LEFT_CONTROL] || io.KeysDown[GLFW_KEY_RIGHT_CONTROL];
  io.KeyShift = io.KeysDown[GLFW_KEY_LEFT_SHIFT] || io.KeysDown[GLFW_KEY_RIGHT_SHIFT];
  io.KeyAlt = io.KeysDown[GLFW_KEY_LEFT_ALT] || io.KeysDown[GLFW_KEY_RIGHT_ALT];
  io.KeySuper = io.KeysDown[GLFW_KEY_LEFT_SUPER] || io.KeysDown[GLFW_KEY_RIGHT_SUPER];
}

void handle_shortcuts(App& app) {
  std::vector<KeyPress> presses;
  presses.swap(app.input.key_presses);
  // Keys typed into a text field belong to the field (Ctrl+Z there is the field's own undo).
  if (ImGui::GetIO().WantTextInput) return;
  for (const KeyPress& press : presses) {
    const bool ctrl = (press.mods & GLFW_MOD_CONTROL) != 0;
    const bool shift = (press.mods & GLFW_MOD_SHIFT) != 0;
    if (ctrl && press.key == GLFW_KEY_Z) {
      shift ? app.commands.redo() : app.commands.undo();
    } else if (ctrl && press.key == GLFW_KEY_Y) {
      app.commands.redo();
    }
    if (press.repeat) continue;  // only undo and redo auto-repeat
    if (press.key == GLFW_KEY_F1) app.windows.help = !app.windows.help;
    if (ctrl && press.key == GLFW_KEY_S) {
      shift ? save_scene_shortcut(app) : app.exports.start(app.view.screenshot_kind);
    }
    if (ctrl && press.key == GLFW_KEY_O) {
      app.session.browser.show(BrowsePurpose::open_scene,
                               scene_folder(app.document.scene().path, app.view.screenshot_dir),
                               "");
    }
    if (ctrl && press.key == GLFW_KEY_Q) app.files.request_quit();
    if (ctrl && press.key == GLFW_KEY_B) snapshot_and_compare(app.commands, app.snapshot, app.view);
    if (press.mods == 0 && press.key >= GLFW_KEY_1 && press.key <= GLFW_KEY_5 &&
        !ImGui::IsAnyItemActive()) {
      const ViewMode modes[5] = {ViewMode::render, ViewMode::terms, ViewMode::single, ViewMode::ab,
                                 ViewMode::lobe};
      app.view.mode = modes[press.key - GLFW_KEY_1];
    }
    if (press.mods == 0 && press.key == GLFW_KEY_I && !ImGui::IsAnyItemActive()) {
      app.view.show_inspector = !app.view.show_inspector;
    }
    if (press.key == GLFW_KEY_ESCAPE) {
      app.windows.help = false;
      app.session.browser.open = false;
      close_menus();
    }
  }
}

}  // namespace gloss

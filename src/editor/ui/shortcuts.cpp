// Keyboard shortcuts (listed in the help window and docs/editor.md) and the input plumbing under
// them. Dear ImGui 1.86 reads key state once per frame, so a press and release that arrive
// between two frames would be lost: shortcuts read a queue of GLFW key events instead, and such
// taps are replayed to ImGui as held for one frame (Enter in a text field, Backspace ...).
#include <string>

#include <imgui.h>
#include <imgui_internal.h>

#include "editor/ui/shortcuts.h"

#include <algorithm>

#include "base/text/ascii.h"
#include "editor/model/session/file_defaults.h"
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

// The keys on objects (issue 24): those on the selection do nothing without one.
void object_action(App& app, ShortcutAction action) {
  using A = ShortcutAction;
  const Scene& scene = app.document.scene();
  const int count = static_cast<int>(scene.objects.size());
  if (action == A::show_all_objects) {
    std::vector<int> all(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) all[static_cast<std::size_t>(i)] = i;
    if (count > 0) app.commands.execute(SetHidden{all, false});
    return;
  }
  const std::vector<int> objects = selected_objects(app.selection, count);
  if (objects.empty()) return;
  if (action == A::frame_selection) frame_selection(app.commands, app.selection);
  if (action == A::delete_objects && app.commands.execute(DeleteObjects{objects})) {
    select_only(app.selection, std::max(objects.front() - 1, 0));
  }
  if (action == A::duplicate_objects && app.commands.execute(DuplicateObjects{objects})) {
    std::vector<int> copies;
    for (std::size_t k = 0; k < objects.size(); ++k) copies.push_back(count + int(k));
    select_all_of(app.selection, copies);
  }
  if (action == A::hide_objects) {
    const bool any_hidden =
        std::any_of(objects.begin(), objects.end(), [&](int i) { return scene.objects[i].hidden; });
    app.commands.execute(SetHidden{objects, !any_hidden});
  }
  if (action == A::solo_objects) app.commands.execute(SoloObjects{objects});
  if (action == A::rename_object) {
    app.outliner.renaming = app.selection.object;
    app.outliner.rename_text = scene.objects[static_cast<std::size_t>(objects.front())].name;
    app.outliner.focus_rename = true;
  }
}

// Ctrl+Shift+S: saves over the scene's own file; a scene without one, or a file gloss ships,
// asks for a name in the user's folder instead.
void save_scene_shortcut(App& app) {
  const std::string& path = app.document.scene().path;
  if (!saves_in_place(path)) {
    app.session.browser.start(BrowsePurpose::save_scene, path, scene_file_name(path));
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

const std::vector<Shortcut>& shortcuts() {
  constexpr int ctrl = GLFW_MOD_CONTROL, shift = GLFW_MOD_SHIFT, alt = GLFW_MOD_ALT;
  using A = ShortcutAction;
  static const std::vector<Shortcut> table = {
      {GLFW_KEY_F1, 0, A::help, "F1", "show or hide this help"},
      {GLFW_KEY_Z, ctrl, A::undo, "Ctrl+Z", "undo", true},
      {GLFW_KEY_Z, ctrl | shift, A::redo, "Ctrl+Shift+Z, Ctrl+Y", "redo", true},
      {GLFW_KEY_Y, ctrl, A::redo, "", "", true},
      {GLFW_KEY_S, ctrl, A::screenshot, "Ctrl+S", "screenshot (the kind chosen in View & Quality)"},
      {GLFW_KEY_S, ctrl | shift, A::save_scene, "Ctrl+Shift+S",
       "save the scene (asks for a name when it has none)"},
      {GLFW_KEY_O, ctrl, A::open_scene, "Ctrl+O", "open a scene"},
      {GLFW_KEY_Q, ctrl, A::quit, "Ctrl+Q", "quit (asks when there are unsaved changes)"},
      {GLFW_KEY_1, 0, A::view_render, "1", "view: the render", false, true},
      {GLFW_KEY_2, 0, A::view_terms, "2", "view: the terms, 2 x 2", false, true},
      {GLFW_KEY_3, 0, A::view_single, "3", "view: one term", false, true},
      {GLFW_KEY_4, 0, A::view_ab, "4", "view: A/B with the heat map of |A - B|", false, true},
      {GLFW_KEY_5, 0, A::view_lobe, "5", "view: the BRDF lobe of the selected material", false,
       true},
      {GLFW_KEY_I, 0, A::inspector, "I", "show or hide the pixel inspector", false, true},
      {GLFW_KEY_B, ctrl, A::snapshot, "Ctrl+B",
       "snapshot: keep the scene now as A, compare later edits (B) with it"},
      {GLFW_KEY_SPACE, ctrl, A::maximise_viewport, "Ctrl+Space",
       "maximise the viewport (hide the panels), or restore them"},
      {GLFW_KEY_LEFT_BRACKET, 0, A::toggle_left_panel, "[",
       "collapse the Material panel to a strip, or expand it", false, true},
      {GLFW_KEY_RIGHT_BRACKET, 0, A::toggle_right_panels, "]",
       "collapse the Outliner, Lights & Scene and View & Quality panels, or expand them", false,
       true},
      {GLFW_KEY_ESCAPE, 0, A::close, "Esc",
       "close an open menu or list, this help, the file panel"},
      // Objects (issue 24; docs/editor.md, "Objects").
      {GLFW_KEY_W, 0, A::gizmo_move, "W / E / R", "the gizmo moves / rotates / scales", false,
       true},
      {GLFW_KEY_E, 0, A::gizmo_rotate, "", "", false, true},
      {GLFW_KEY_R, 0, A::gizmo_scale, "", "", false, true},
      {GLFW_KEY_F, 0, A::frame_selection, "F", "frame the selected objects", false, true},
      {GLFW_KEY_DELETE, 0, A::delete_objects, "Delete", "delete the selected objects", false, true},
      {GLFW_KEY_D, ctrl, A::duplicate_objects, "Ctrl+D", "duplicate the selected objects", false,
       true},
      {GLFW_KEY_H, 0, A::hide_objects, "H", "hide the selected objects, or show them", false, true},
      {GLFW_KEY_H, shift, A::solo_objects, "Shift+H", "solo: show the selected objects alone",
       false, true},
      {GLFW_KEY_H, alt, A::show_all_objects, "Alt+H", "show every object", false, true},
      {GLFW_KEY_F2, 0, A::rename_object, "F2", "rename the selected object (in the Outliner)",
       false, true},
  };
  return table;
}

std::string shortcut_name(const Shortcut& s) {
  std::string name;
  if (s.mods & GLFW_MOD_CONTROL) name += "Ctrl+";
  if (s.mods & GLFW_MOD_SHIFT) name += "Shift+";
  if (s.mods & GLFW_MOD_ALT) name += "Alt+";
  if (s.mods & GLFW_MOD_SUPER) name += "Super+";
  if (s.key >= GLFW_KEY_A && s.key <= GLFW_KEY_Z) return name + static_cast<char>(s.key);
  if (s.key >= GLFW_KEY_0 && s.key <= GLFW_KEY_9) return name + static_cast<char>(s.key);
  if (s.key >= GLFW_KEY_F1 && s.key <= GLFW_KEY_F12) {
    return name + "F" + std::to_string(s.key - GLFW_KEY_F1 + 1);
  }
  switch (s.key) {
    case GLFW_KEY_SPACE:
      return name + "Space";
    case GLFW_KEY_ESCAPE:
      return name + "Esc";
    case GLFW_KEY_LEFT_BRACKET:
      return name + "[";
    case GLFW_KEY_RIGHT_BRACKET:
      return name + "]";
    case GLFW_KEY_DELETE:
      return name + "Delete";
    default:
      return name + "key " + std::to_string(s.key);
  }
}

const Shortcut* find_shortcut(const std::string& keys) {
  for (const Shortcut& s : shortcuts()) {
    if (ascii_equal_ignoring_case(shortcut_name(s), keys)) return &s;
  }
  return nullptr;
}

namespace {

void act(App& app, ShortcutAction action) {
  LayoutState& layout = app.layout;
  switch (action) {
    case ShortcutAction::help:
      app.windows.help = !app.windows.help;
      break;
    case ShortcutAction::undo:
      app.commands.undo();
      break;
    case ShortcutAction::redo:
      app.commands.redo();
      break;
    case ShortcutAction::screenshot:
      app.exports.start(app.view.screenshot_kind);
      break;
    case ShortcutAction::save_scene:
      save_scene_shortcut(app);
      break;
    case ShortcutAction::open_scene:
      app.session.browser.start(BrowsePurpose::open_scene, app.document.scene().path, "");
      break;
    case ShortcutAction::quit:
      app.files.request_quit();
      break;
    case ShortcutAction::snapshot:
      snapshot_and_compare(app.commands, app.snapshot, app.view);
      break;
    case ShortcutAction::view_render:
      app.view.mode = ViewMode::render;
      break;
    case ShortcutAction::view_terms:
      app.view.mode = ViewMode::terms;
      break;
    case ShortcutAction::view_single:
      app.view.mode = ViewMode::single;
      break;
    case ShortcutAction::view_ab:
      app.view.mode = ViewMode::ab;
      break;
    case ShortcutAction::view_lobe:
      app.view.mode = ViewMode::lobe;
      break;
    case ShortcutAction::inspector:
      app.view.show_inspector = !app.view.show_inspector;
      break;
    case ShortcutAction::maximise_viewport:
      layout.panels.viewport_maximised = !layout.panels.viewport_maximised;
      break;
    case ShortcutAction::toggle_left_panel:
      layout.panels.viewport_maximised = false;
      layout.panels.left_collapsed = !layout.panels.left_collapsed;
      break;
    case ShortcutAction::toggle_right_panels:
      layout.panels.viewport_maximised = false;
      layout.panels.right_collapsed = !layout.panels.right_collapsed;
      break;
    case ShortcutAction::close:
      app.windows.help = false;
      app.session.browser.open = false;
      close_menus();
      break;
    case ShortcutAction::gizmo_move:
      app.view.gizmo = GizmoMode::move;
      break;
    case ShortcutAction::gizmo_rotate:
      app.view.gizmo = GizmoMode::rotate;
      break;
    case ShortcutAction::gizmo_scale:
      app.view.gizmo = GizmoMode::scale;
      break;
    case ShortcutAction::frame_selection:
    case ShortcutAction::delete_objects:
    case ShortcutAction::duplicate_objects:
    case ShortcutAction::hide_objects:
    case ShortcutAction::solo_objects:
    case ShortcutAction::show_all_objects:
    case ShortcutAction::rename_object:
      object_action(app, action);
      break;
  }
}

}  // namespace

void handle_shortcuts(App& app) {
  std::vector<KeyPress> presses;
  presses.swap(app.input.key_presses);
  // Keys typed into a text field belong to the field (Ctrl+Z there is the field's own undo).
  if (ImGui::GetIO().WantTextInput) return;
  // A question (recover, quit, open over unsaved edits) is answered first: no key acts behind it
  // (Esc is its Cancel, handled by the question itself).
  if (ImGui::GetTopMostPopupModal() != nullptr) return;
  constexpr int kModifiers = GLFW_MOD_CONTROL | GLFW_MOD_SHIFT | GLFW_MOD_ALT | GLFW_MOD_SUPER;
  for (const KeyPress& press : presses) {
    const int mods = press.mods & kModifiers;
    for (const Shortcut& s : shortcuts()) {
      if (s.key != press.key || s.mods != mods) continue;
      if (press.repeat && !s.repeats) break;
      // A plain key while a slider is dragged or a field edited belongs to it.
      if (s.plain && ImGui::IsAnyItemActive()) break;
      act(app, s.action);
      break;
    }
  }
}

}  // namespace gloss

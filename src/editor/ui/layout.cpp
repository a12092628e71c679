// The window's layout (editor/model/layout/panel_layout.h has its rules): the menu bar on top, the
// Material and Reference panels on the left, the Outliner over the Lights & Scene and View &
// Quality panels on the right, the viewport between them, the status bar below, the floating
// windows and questions over them. Panels collapse to strips and the viewport can take the whole
// width; the splitters and the panels' collapse buttons are small windows kept above the panels.
// Each panel is handed only the parts of the App it may touch (panels/panels.h).
#include <algorithm>
#include <cmath>

#include <imgui.h>
#include <imgui_internal.h>

#include "editor/ui/app.h"
#include "editor/ui/panels/panels.h"

namespace gloss {

namespace {

ImVec2 at(const LayoutRect& r, ImVec2 origin) {
  return ImVec2(origin.x + r.x, origin.y + r.y);
}
ImVec2 size_of(const LayoutRect& r) {
  return ImVec2(r.w, r.h);
}

// A small undecorated window over the panels at r (splitters, buttons, strips). The panels are
// kept at the back (send_to_back), so these stay above them even after a click on a panel, and
// the floating windows above both.
bool begin_overlay(const char* id, const LayoutRect& r, ImVec2 origin, bool background = false) {
  ImGui::SetNextWindowPos(at(r, origin));
  ImGui::SetNextWindowSize(size_of(r));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1, 1));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav |
                                 (background ? 0 : ImGuiWindowFlags_NoBackground);
  const bool open = ImGui::Begin(id, nullptr, flags);
  ImGui::PopStyleVar(3);
  return open;
}

// A handle over the border between two panels, kSplitterWidth pixels wide: dragging it moves the
// border; hovered or dragged, it lights up and the cursor shows the resize arrows. vertical: a
// left-right border (moved along x), else a top-bottom one. Returns the drag this frame.
float splitter(const char* id, const LayoutRect& r, ImVec2 origin, bool vertical) {
  if (!r.visible()) return 0.0f;
  float moved = 0.0f;
  if (begin_overlay(id, r, origin)) {
    const ImVec2 pos = at(r, origin);
    ImGui::InvisibleButton("##handle", size_of(r));
    if (ImGui::IsItemHovered() || ImGui::IsItemActive()) {
      ImGui::SetMouseCursor(vertical ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
      ImGui::GetWindowDrawList()->AddRectFilled(
          pos, ImVec2(pos.x + r.w, pos.y + r.h),
          ImGui::GetColorU32(ImGui::IsItemActive() ? ImGuiCol_SeparatorActive
                                                   : ImGuiCol_SeparatorHovered));
    }
    if (ImGui::IsItemActive())
      moved = vertical ? ImGui::GetIO().MouseDelta.x : ImGui::GetIO().MouseDelta.y;
  }
  ImGui::End();
  return moved;
}

// A collapsed panel: a strip with the panels' names written down it; a click expands them.
bool strip(const char* id, const LayoutRect& r, ImVec2 origin, const char* names,
           const char* tooltip) {
  if (!r.visible()) return false;
  bool clicked = false;
  if (begin_overlay(id, r, origin, true)) {
    const ImVec2 pos = at(r, origin);
    clicked = ImGui::InvisibleButton("##expand", size_of(r));
    ImDrawList* list = ImGui::GetWindowDrawList();
    list->AddRectFilled(pos, ImVec2(pos.x + r.w, pos.y + r.h),
                        ImGui::GetColorU32(ImGuiCol_TitleBg));
    if (ImGui::IsItemHovered()) {
      list->AddRectFilled(pos, ImVec2(pos.x + r.w, pos.y + r.h),
                          ImGui::GetColorU32(ImGuiCol_HeaderHovered));
      ImGui::SetTooltip("%s", tooltip);
    }
    // One letter a line, centred; '|' starts the next name after a gap.
    const float line = ImGui::GetTextLineHeight();
    float y = pos.y + 8.0f;
    const ImU32 colour = ImGui::GetColorU32(ImGuiCol_Text);
    for (const char* c = names; *c != '\0' && y + line < pos.y + r.h; ++c) {
      if (*c == '|') {
        y += line;
        continue;
      }
      const char text[2] = {*c, '\0'};
      const float w = ImGui::CalcTextSize(text).x;
      list->AddText(ImVec2(pos.x + (r.w - w) * 0.5f, y), colour, text);
      y += *c == ' ' ? line * 0.5f : line;
    }
  }
  ImGui::End();
  return clicked;
}

// A small button over a corner of a panel or the viewport (collapse, maximise).
bool corner_button(const char* id, const char* label, const char* tooltip, float right, float top) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float w = ImGui::CalcTextSize(label).x + style.FramePadding.x * 2.0f;
  const float h = ImGui::GetFrameHeight();
  const LayoutRect r{right - w - 2.0f, top + 1.0f, w, h};
  bool clicked = false;
  if (begin_overlay(id, r, ImVec2(0, 0))) {
    clicked = ImGui::Button(label, ImVec2(w, h));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
  }
  ImGui::End();
  return clicked;
}

// The docked windows (panels, viewport, status bar) behind everything else: a click on a panel
// would otherwise bring it over the splitters on its border, leaving half of their width.
void send_to_back(const char* name) {
  if (ImGuiWindow* w = ImGui::FindWindowByName(name)) ImGui::BringWindowToDisplayBack(w);
}

// Floating windows and questions stay inside the main window: one that a smaller window (or a
// position kept from a larger one) leaves partly outside is moved back in, and shrunk when it is
// larger than the window. Panels, the viewport and the bars are placed every frame anyway.
void keep_windows_inside() {
  ImGuiContext& g = *ImGui::GetCurrentContext();
  const ImGuiViewport* main = ImGui::GetMainViewport();
  const ImVec2 lo = main->Pos;
  const ImVec2 hi(main->Pos.x + main->Size.x, main->Pos.y + main->Size.y);
  for (ImGuiWindow* w : g.Windows) {
    if (!w->WasActive || (w->Flags & (ImGuiWindowFlags_ChildWindow | ImGuiWindowFlags_Tooltip)) ||
        w->Collapsed) {
      continue;
    }
    ImVec2 size = w->Size;
    if (size.x > main->Size.x || size.y > main->Size.y) {
      size = ImVec2(std::min(size.x, main->Size.x), std::min(size.y, main->Size.y));
      ImGui::SetWindowSize(w, size, ImGuiCond_Always);
    }
    const ImVec2 pos(std::clamp(w->Pos.x, lo.x, hi.x - size.x),
                     std::clamp(w->Pos.y, lo.y, hi.y - size.y));
    if (pos.x != w->Pos.x || pos.y != w->Pos.y) ImGui::SetWindowPos(w, pos, ImGuiCond_Always);
  }
}

// While a question (a modal) is open no tooltip shows: a panel drawn before the question opened,
// in the same frame, still saw its item hovered, and ImGui draws tooltips above every window.
void hide_tooltips_under_a_question() {
  if (ImGui::GetTopMostPopupModal() == nullptr) return;
  for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows) {
    if ((w->Flags & ImGuiWindowFlags_Tooltip) != 0) w->Hidden = true;
  }
}

}  // namespace

void draw_layout(App& app) {
  keep_windows_inside();
  draw_menu_bar(app.commands, app.selection, app.view, app.snapshot, app.session, app.files,
                app.exports, app.windows, app.layout);
  LayoutState& layout = app.layout;
  const ImGuiViewport* main = ImGui::GetMainViewport();
  const ImVec2 origin = main->Pos;
  const PanelLayout l = panel_layout(layout.panels, main->Size.x, main->Size.y,
                                     ImGui::GetFrameHeight(), ImGui::GetFrameHeight() + 6.0f);
  layout.last = l;
  if (l.left.visible()) {
    draw_material_panel(app.commands, app.selection, app.view, app.material_panel, app.library,
                        app.files, app.session.browser, at(l.left, origin), size_of(l.left));
    draw_reference_panel(app.commands, app.selection, app.view, app.reference_panel,
                         at(l.reference, origin), size_of(l.reference));
  }
  if (l.lights.visible()) {
    draw_outliner(app.commands, app.selection, app.outliner, app.session.browser,
                  at(l.outliner, origin), size_of(l.outliner));
    draw_lights_panel(app.commands, app.selection, app.view, app.session.browser,
                      at(l.lights, origin), size_of(l.lights));
    draw_view_panel(app.commands, app.view, app.viewport, app.snapshot, app.windows, app.exports,
                    at(l.view, origin), size_of(l.view));
  }
  const ImVec2 viewport_pos = at(l.viewport, origin);
  const ImVec2 viewport_size = size_of(l.viewport);
  app.viewport.draw(app.commands, app.view, app.selection, app.input,
                    app.snapshot ? &*app.snapshot : nullptr, app.now_s(), viewport_pos,
                    viewport_size);
  draw_inspector(app.inspector, app.view, app.document, app.snapshot, app.viewport, viewport_pos,
                 viewport_size);
  for (const char* name :
       {"Material", "Outliner", "Lights & Scene", "View & Quality", "Viewport", "##status"}) {
    send_to_back(name);
  }
  // Over the panels, after them: splitters, the collapse buttons, the strips.
  PanelChoices& panels = layout.panels;
  panels.left_width = l.left_width + splitter("##split-left", l.left_split, origin, true);
  panels.right_width = l.right_width - splitter("##split-right", l.right_split, origin, true);
  panels.outliner_share +=
      splitter("##split-outliner", l.outliner_split, origin, false) / std::max(l.viewport.h, 1.0f);
  panels.lights_share += splitter("##split-lights", l.lights_split, origin, false) /
                         std::max(l.lights.h + l.view.h, 1.0f);
  panels.material_share +=
      splitter("##split-material", l.material_split, origin, false) / std::max(l.viewport.h, 1.0f);
  clamp_panel_widths(panels, main->Size.x);
  if (l.left.visible() &&
      corner_button("##collapse-left", "<", "collapse Material and Reference to a strip ([)",
                    origin.x + l.left.right(), origin.y + l.left.y)) {
    panels.left_collapsed = true;
  }
  if (l.lights.visible() &&
      corner_button("##collapse-right", ">",
                    "collapse the Outliner, Lights & Scene and View & Quality to a strip (])",
                    origin.x + l.outliner.right(), origin.y + l.outliner.y)) {
    panels.right_collapsed = true;
  }
  if (strip("##strip-left", l.left_strip, origin, "Material", "Material: click to expand ([)")) {
    panels.left_collapsed = false;
  }
  if (strip("##strip-right", l.right_strip, origin, "Outliner|Lights|View",
            "Outliner, Lights & Scene, View & Quality: click to expand (])")) {
    panels.right_collapsed = false;
  }
  if (corner_button("##maximise", panels.viewport_maximised ? "restore panels" : "maximise",
                    panels.viewport_maximised ? "show the panels again (Ctrl+Space)"
                                              : "the viewport takes the whole width (Ctrl+Space)",
                    viewport_pos.x + viewport_size.x, viewport_pos.y)) {
    panels.viewport_maximised = !panels.viewport_maximised;
  }
  draw_status_bar(app.viewport, app.view, app.frame.times, app.notices, app.session,
                  at(l.status, origin), size_of(l.status));
  // The Quality window opens over the viewport's right side (its table needs more width than a
  // side panel has); it can be moved, resized and closed.
  const float quality_w = std::min(480.0f, viewport_size.x);
  draw_quality_panel(app.quality, app.windows, app.view, app.commands,
                     ImVec2(viewport_pos.x + viewport_size.x - quality_w, viewport_pos.y),
                     ImVec2(quality_w, viewport_size.y));
  // Below the viewport's maximise button; in the lobe view, whose controls run along its top,
  // above its bottom edge.
  if (app.view.mode == ViewMode::lobe) {
    app.notices.draw(viewport_pos.x + viewport_size.x, viewport_pos.y + viewport_size.y - 12.0f,
                     false);
  } else {
    app.notices.draw(viewport_pos.x + viewport_size.x,
                     viewport_pos.y + ImGui::GetFrameHeight() + 8.0f, true);
  }
  FileBrowser& browser = app.session.browser;
  std::string chosen;
  if (browser.draw(app.session.recent.of(recent_kind(browser.purpose)), chosen)) {
    app.files.browser_action(chosen);
  }
  draw_help_window(app.windows, app.session);
  draw_recovery_modal(app.session, app.files);
  draw_quit_modal(app.windows, app.commands, app.files, app.run);
  draw_open_modal(app.session, app.commands, app.files);
  hide_tooltips_under_a_question();
}

}  // namespace gloss

// The window's layout: the menu bar on top, the Material and Reference panels on the left, the
// Lights & Scene and View & Quality panels on the right, the viewport between them, the status
// bar below, the floating windows and questions over them. Each is handed only the parts of
// the App it may touch (panels/panels.h).
#include <algorithm>
#include <cmath>

#include <imgui.h>

#include "editor/ui/app.h"
#include "editor/ui/panels/panels.h"

namespace gloss {

namespace {

// A thin handle over the border between two panels: dragging it moves the border. vertical:
// a left-right border (moved along x), else a top-bottom one. Returns the drag this frame.
float splitter(const char* id, ImVec2 pos, ImVec2 size, bool vertical) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1, 1));
  ImGui::Begin(id, nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
  ImGui::PopStyleVar(2);
  ImGui::InvisibleButton("##handle", size);
  float moved = 0.0f;
  if (ImGui::IsItemHovered() || ImGui::IsItemActive()) {
    ImGui::SetMouseCursor(vertical ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
    ImGui::GetWindowDrawList()->AddRectFilled(
        pos, ImVec2(pos.x + size.x, pos.y + size.y),
        ImGui::GetColorU32(ImGui::IsItemActive() ? ImGuiCol_SeparatorActive
                                                 : ImGuiCol_SeparatorHovered));
  }
  if (ImGui::IsItemActive())
    moved = vertical ? ImGui::GetIO().MouseDelta.x : ImGui::GetIO().MouseDelta.y;
  ImGui::End();
  return moved;
}

}  // namespace

void draw_layout(App& app) {
  draw_menu_bar(app.commands, app.view, app.snapshot, app.session, app.files, app.exports,
                app.windows);
  LayoutState& layout = app.layout;
  const ImGuiViewport* main = ImGui::GetMainViewport();
  const float menu_h = ImGui::GetFrameHeight();
  const float status_h = ImGui::GetFrameHeight() + 6.0f;
  const float top = main->Pos.y + menu_h;
  const float height = std::max(main->Size.y - menu_h - status_h, 1.0f);
  const float default_side = std::clamp(main->Size.x * 0.23f, 280.0f, 420.0f);
  // Each side panel keeps between 220 pixels and 40% of the window.
  const float most = std::max(220.0f, main->Size.x * 0.4f);
  if (layout.left_width <= 0.0f) layout.left_width = default_side;
  if (layout.right_width <= 0.0f) layout.right_width = default_side;
  layout.left_width = std::clamp(layout.left_width, 220.0f, most);
  layout.right_width = std::clamp(layout.right_width, 220.0f, most);
  layout.lights_share = std::clamp(layout.lights_share, 0.15f, 0.85f);
  layout.material_share = std::clamp(layout.material_share, 0.2f, 0.9f);
  const float side = layout.left_width;
  const float right_side = layout.right_width;
  const float left = main->Pos.x, right = main->Pos.x + main->Size.x;
  const float lights_h = std::floor(height * layout.lights_share);
  const float material_h = std::floor(height * layout.material_share);
  draw_material_panel(app.commands, app.selection, app.view, app.material_panel, app.library,
                      app.session.browser, ImVec2(left, top), ImVec2(side, material_h));
  draw_reference_panel(app.commands, app.selection, app.view, app.reference_panel,
                       ImVec2(left, top + material_h), ImVec2(side, height - material_h));
  draw_lights_panel(app.commands, app.selection, app.view, app.session.browser,
                    ImVec2(right - right_side, top), ImVec2(right_side, lights_h));
  draw_view_panel(app.commands, app.view, app.viewport, app.snapshot, app.windows, app.exports,
                  ImVec2(right - right_side, top + lights_h),
                  ImVec2(right_side, height - lights_h));
  const ImVec2 viewport_pos(left + side, top);
  const ImVec2 viewport_size(std::max(main->Size.x - side - right_side, 1.0f), height);
  app.viewport.draw(app.commands, app.view, app.selection, app.input, app.now_s(), viewport_pos,
                    viewport_size);
  draw_inspector(app.inspector, app.view, app.document, app.snapshot, app.viewport, viewport_pos,
                 viewport_size);
  // The splitters go over the borders, after the panels so that they are on top.
  layout.left_width +=
      splitter("##split-left", ImVec2(left + side - 3.0f, top), ImVec2(6.0f, height), true);
  layout.right_width -=
      splitter("##split-right", ImVec2(right - right_side - 3.0f, top), ImVec2(6.0f, height), true);
  layout.lights_share +=
      splitter("##split-lights", ImVec2(right - right_side, top + lights_h - 3.0f),
               ImVec2(right_side, 6.0f), false) /
      height;
  layout.material_share += splitter("##split-material", ImVec2(left, top + material_h - 3.0f),
                                    ImVec2(side, 6.0f), false) /
                           height;
  draw_status_bar(app.viewport, app.view, app.frame.times, app.notices, app.session,
                  ImVec2(left, top + height), ImVec2(main->Size.x, status_h));
  // The Quality window opens over the viewport's right side (its table needs more width than a
  // side panel has); it can be moved, resized and closed.
  const float quality_w = std::min(480.0f, viewport_size.x);
  draw_quality_panel(app.quality, app.windows, app.view, app.commands,
                     ImVec2(viewport_pos.x + viewport_size.x - quality_w, top),
                     ImVec2(quality_w, height));
  app.notices.draw(viewport_pos.x + viewport_size.x, top + height);
  FileBrowser& browser = app.session.browser;
  std::string chosen;
  if (browser.draw(app.session.recent.of(recent_kind(browser.purpose)), chosen)) {
    app.files.browser_action(chosen);
  }
  draw_help_window(app.windows, app.session);
  draw_recovery_modal(app.session, app.files);
  draw_quit_modal(app.windows, app.commands, app.files, app.run);
  draw_open_modal(app.session, app.commands, app.files);
}

}  // namespace gloss

// The viewport window: its layout, the mouse gestures (orbit, pan, zoom, click to select, drag a
// light marker) and the light markers. Gestures become commands through the command door.
#include "editor/ui/viewport/viewport.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include <imgui.h>

#include "editor/model/view/camera_controller.h"
#include "editor/ui/parts/commands.h"
#include "editor/ui/parts/input_state.h"
#include "editor/ui/parts/selection.h"
#include "engine/pick.h"

namespace gloss {

namespace {

constexpr float kMarkerRadius = 7.0f;  // screen pixels
constexpr float kClickSlop = 3.0f;     // pixels a click may move and still select
constexpr float kLabelRoom = 30.0f;    // off-view arrows at a pane's top sit below its label

bool inside(const Pane& pane, ImVec2 p) {
  return p.x >= pane.min.x && p.y >= pane.min.y && p.x < pane.min.x + pane.size.x &&
         p.y < pane.min.y + pane.size.y;
}

}  // namespace

Camera Viewport::pane_camera(const Scene& scene) const {
  if (!m_fill || m_panes[0].size.y < 1.0f) return scene.camera;
  const float document = static_cast<float>(scene.render.width) / scene.render.height;
  return overscan_camera(scene.camera, document, m_panes[0].size.x / m_panes[0].size.y);
}

EdgeMarker Viewport::light_marker(const Scene& scene, int light, const Pane& pane) const {
  return edge_marker(
      pane_camera(scene), static_cast<int>(pane.size.x), static_cast<int>(pane.size.y),
      scene.lights[static_cast<std::size_t>(light)].position, kMarkerRadius + 6.0f, kLabelRoom);
}

int Viewport::pane_at(ImVec2 screen) const {
  for (int i = 0; i < m_pane_count; ++i) {
    if (inside(m_panes[i], screen)) return i;
  }
  return -1;
}

bool Viewport::render_pixel_at(ImVec2 p, int width, int height, int& x, int& y) const {
  for (int i = 0; i < m_pane_count; ++i) {
    // Each pane's frame has the document's aspect and maps onto the whole render; around it
    // (a pane that fills its cell) lies no pixel of the render.
    const Pane& frame = m_frames[i];
    if (!inside(frame, p)) continue;
    x = std::clamp(static_cast<int>((p.x - frame.min.x) / frame.size.x * width), 0, width - 1);
    y = std::clamp(static_cast<int>((p.y - frame.min.y) / frame.size.y * height), 0, height - 1);
    return true;
  }
  return false;
}

// Screen size of one render pixel in pane i and the marker's half width around it.
namespace {
float marker_radius(const Pane& pane, int width) {
  return std::max(4.0f, 0.5f * pane.size.x / static_cast<float>(width) + 3.0f);
}
ImVec2 pixel_centre(const Pane& pane, int x, int y, int width, int height) {
  return ImVec2(pane.min.x + (static_cast<float>(x) + 0.5f) * pane.size.x / width,
                pane.min.y + (static_cast<float>(y) + 0.5f) * pane.size.y / height);
}
}  // namespace

// A click with the inspector open pins the pixel under it; a click on the pinned pixel's marker
// unpins it.
void Viewport::pin_inspected_pixel(ViewSettings& view, const RenderSettings& render,
                                   ImVec2 p) const {
  int x = 0, y = 0;
  if (!view.show_inspector || !render_pixel_at(p, render.width, render.height, x, y)) {
    return;
  }
  if (view.inspect_pinned) {
    const Pane& pane = m_frames[std::max(pane_at(p), 0)];
    const ImVec2 c =
        pixel_centre(pane, view.inspect_x, view.inspect_y, render.width, render.height);
    const float r = marker_radius(pane, render.width) + 1.0f;
    if (std::abs(p.x - c.x) <= r && std::abs(p.y - c.y) <= r) {
      view.inspect_pinned = false;
      return;
    }
  }
  view.inspect_pinned = true;
  view.inspect_x = x;
  view.inspect_y = y;
}

// The pinned pixel's place in every image pane: a small square around it.
void Viewport::draw_inspected_pixel(const ViewSettings& view, const RenderSettings& render,
                                    ImDrawList* list) const {
  if (!view.show_inspector || !view.inspect_pinned) return;
  for (int i = 0; i < m_pane_count; ++i) {
    const Pane& pane = m_frames[i];
    const ImVec2 c =
        pixel_centre(pane, view.inspect_x, view.inspect_y, render.width, render.height);
    const float r = marker_radius(pane, render.width);
    list->AddRect(ImVec2(c.x - r - 1.0f, c.y - r - 1.0f), ImVec2(c.x + r + 1.0f, c.y + r + 1.0f),
                  IM_COL32(0, 0, 0, 255), 0.0f, 0, 3.0f);
    list->AddRect(ImVec2(c.x - r, c.y - r), ImVec2(c.x + r, c.y + r), IM_COL32(255, 60, 200, 255),
                  0.0f, 0, 1.5f);
  }
}

bool Viewport::moving_gesture(double now_s) const {
  if (m_drag_button < 0) return gesture_active(now_s);  // a recent wheel zoom
  return m_drag_light >= 0 || m_drag_aim >= 0 || m_drag_environment || m_gizmo.dragging() ||
         (m_drag_distance > kClickSlop && !m_marker_pressed);
}

void Viewport::draw(Commands& commands, ViewSettings& view, Selection& selection,
                    const InputState& input, const Snapshot* snapshot, double now_s, ImVec2 pos,
                    ImVec2 size) {
  m_pos = pos;
  m_size = size;
  m_framebuffer_scale = ImGui::GetIO().DisplayFramebufferScale.x;
  // The panes in the document's aspect (what the exports render), arranged to fill the
  // viewport (pane_layout.h); A/B's legend beside its three images.
  const RenderSettings& render = commands.scene().render;
  const float aspect = static_cast<float>(render.width) / static_cast<float>(render.height);
  const PaneArrangement arrangement =
      arrange_panes(view.mode, LayoutRect{pos.x, pos.y, size.x, size.y}, aspect);
  m_pane_count = arrangement.count;
  m_fill = arrangement.fill;
  for (int i = 0; i < m_pane_count; ++i) {
    const LayoutRect& r = arrangement.panes[i];
    const LayoutRect& f = arrangement.frames[i];
    m_panes[i] = Pane{ImVec2(r.x, r.y), ImVec2(r.w, r.h)};
    m_frames[i] = Pane{ImVec2(f.x, f.y), ImVec2(f.w, f.h)};
  }
  m_legend.min = ImVec2(arrangement.legend.x, arrangement.legend.y);
  m_legend.size = ImVec2(arrangement.legend.w, arrangement.legend.h);

  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  const ImGuiWindowFlags flags =
      ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
      ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse |
      ImGuiWindowFlags_NoBackground;  // the image covers it
  const bool open = ImGui::Begin("Viewport", nullptr, flags);
  ImGui::PopStyleVar(2);
  m_visible = false;
  m_hover_x = m_hover_y = -1;
  if (!open) {
    ImGui::End();
    return;
  }
  if (view.mode == ViewMode::lobe) {  // the renderer keeps the render pane's size meanwhile
    draw_lobe_view(commands.scene(), selection, view, snapshot, m_lobe, pos, size);
    ImGui::End();
    return;
  }
  draw_panes(view, display_transform(commands.scene().render));
  // The target is copied into the back buffer under ImGui's draw lists (blit(), from
  // run_frame): the window has no background, so it shows through.
  m_visible = true;
  handle_input(commands, view, selection, input, now_s);
  ImDrawList* list = ImGui::GetWindowDrawList();
  draw_labels(view, list);
  if (view.mode == ViewMode::ab) draw_legend(view, list, m_legend);
  draw_light_gizmos(commands.scene(), selection, list);
  draw_light_markers(commands.scene(), selection, list);
  m_gizmo.draw(commands.scene(), pane_camera(commands.scene()), selection, view, m_panes[0].min,
               m_panes[0].size, ImGui::GetIO().MousePos, list);
  draw_inspected_pixel(view, commands.scene().render, list);
  if (!m_frame_a) {
    const char* text = "rendering the first frame ...";
    const ImVec2 t = ImGui::CalcTextSize(text);
    list->AddText(ImVec2(pos.x + (size.x - t.x) * 0.5f, pos.y + (size.y - t.y) * 0.5f),
                  IM_COL32(200, 200, 200, 255), text);
  }
  ImGui::End();
}

void Viewport::draw_light_markers(const Scene& scene, const Selection& selection,
                                  ImDrawList* list) const {
  for (int p = 0; p < m_pane_count; ++p) {
    const Pane& pane = m_panes[p];
    const int w = static_cast<int>(pane.size.x), h = static_cast<int>(pane.size.y);
    list->PushClipRect(pane.min, ImVec2(pane.min.x + pane.size.x, pane.min.y + pane.size.y), true);
    // The selected objects: corner brackets around their projected bounds (the primary's in
    // yellow, with its name), dashed for a hidden one.
    const Camera camera = pane_camera(scene);
    for (int object : selected_objects(selection, static_cast<int>(scene.objects.size()))) {
      glm::vec2 lo, hi;
      if (!screen_bounds(camera, w, h, scene.objects[object], lo, hi)) continue;
      const bool primary = object == selection.object;
      const ImVec2 a(pane.min.x + lo.x - 3.0f, pane.min.y + lo.y - 3.0f);
      const ImVec2 b(pane.min.x + hi.x + 3.0f, pane.min.y + hi.y + 3.0f);
      const float arm = std::min(14.0f, 0.3f * std::min(b.x - a.x, b.y - a.y));
      const ImU32 colour = primary ? IM_COL32(255, 200, 40, 230) : IM_COL32(255, 140, 40, 200);
      const float thick = scene.objects[object].hidden ? 1.0f : 2.0f;
      const ImVec2 corners[4] = {a, ImVec2(b.x, a.y), b, ImVec2(a.x, b.y)};
      for (int c = 0; c < 4; ++c) {
        const float sx = (c == 1 || c == 2) ? -1.0f : 1.0f;
        const float sy = c >= 2 ? -1.0f : 1.0f;
        const ImVec2 k = corners[c];
        list->AddLine(k, ImVec2(k.x + sx * arm, k.y), colour, thick);
        list->AddLine(k, ImVec2(k.x, k.y + sy * arm), colour, thick);
      }
      if (p == 0 && primary) {
        // Inside the pane where the object's box reaches past its left or right edge.
        const std::string label = object_label(scene, object);
        const float width = ImGui::CalcTextSize(label.c_str()).x;
        const float x =
            std::max(std::min(a.x, pane.min.x + pane.size.x - width - 2.0f), pane.min.x + 2.0f);
        list->AddText(ImVec2(x, std::max(a.y - 16.0f, pane.min.y + 20.0f)), colour, label.c_str());
      }
    }
    for (int i = 0; i < static_cast<int>(scene.lights.size()); ++i) {
      if (scene.lights[i].type == LightType::directional) continue;  // no position: its arrow
      const EdgeMarker m = light_marker(scene, i, pane);
      const ImVec2 centre(pane.min.x + m.position.x, pane.min.y + m.position.y);
      const glm::vec3 c = glm::clamp(scene.lights[i].diffuse, glm::vec3(0.0f), glm::vec3(1.0f));
      const ImU32 fill = ImGui::ColorConvertFloat4ToU32(ImVec4(c.x, c.y, c.z, 1.0f));
      const bool selected = i == selection.light;
      const ImU32 ring = selected ? IM_COL32(255, 200, 40, 255) : IM_COL32(20, 20, 20, 255);
      const float r = selected ? kMarkerRadius + 2.0f : kMarkerRadius;
      if (m.on_screen) {
        list->AddCircleFilled(centre, r, fill);
        list->AddCircle(centre, r + 1.5f, ring, 0, 2.0f);
      } else {
        // Off screen: an arrow at the edge pointing toward the light.
        const ImVec2 d(m.direction.x, m.direction.y), n(-m.direction.y, m.direction.x);
        const float len = r + 5.0f;
        const ImVec2 tip(centre.x + d.x * len, centre.y + d.y * len);
        const ImVec2 l(centre.x - d.x * r + n.x * r, centre.y - d.y * r + n.y * r);
        const ImVec2 rr(centre.x - d.x * r - n.x * r, centre.y - d.y * r - n.y * r);
        list->AddTriangleFilled(tip, l, rr, fill);
        list->AddTriangle(tip, l, rr, ring, 2.0f);
      }
      char label[32];
      std::snprintf(label, sizeof label, m.on_screen ? "%d" : "%d (off view)", i);
      const ImVec2 size = ImGui::CalcTextSize(label);
      // Keep the label inside the pane, beside the marker.
      // Right of the marker, or left of it where the pane's right edge is too close.
      float lx = centre.x + r + 3.0f;
      if (lx + size.x > pane.min.x + pane.size.x - 2.0f) lx = centre.x - r - 6.0f - size.x;
      lx = std::max(lx, pane.min.x + 2.0f);
      const float ly = std::clamp(centre.y - r - 6.0f, pane.min.y + 2.0f,
                                  pane.min.y + pane.size.y - size.y - 2.0f);
      list->AddText(ImVec2(lx, ly), IM_COL32(255, 230, 150, 255), label);
    }
    list->PopClipRect();
  }
}

void Viewport::handle_input(Commands& commands, ViewSettings& view, Selection& selection,
                            const InputState& input, double now_s) {
  ImGuiIO& io = ImGui::GetIO();
  ImGui::SetCursorScreenPos(m_pos);
  ImGui::InvisibleButton("##viewport-input", m_size,
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  const Scene& scene = commands.scene();

  if (ImGui::IsItemActivated()) {
    m_drag_button = ImGui::IsMouseClicked(ImGuiMouseButton_Left)    ? ImGuiMouseButton_Left
                    : ImGui::IsMouseClicked(ImGuiMouseButton_Right) ? ImGuiMouseButton_Right
                                                                    : ImGuiMouseButton_Middle;
    // Motion before the press (in the same batch of events) is not part of the drag; motion
    // after it is, even when ImGui sees both in one frame.
    const ImVec2 press = input.press_position[m_drag_button];
    m_drag_press = press;
    m_drag_last = press;
    m_drag_distance = 0.0f;
    m_drag_pane = pane_at(press);
    m_drag_light = -1;
    m_drag_aim = -1;
    m_marker_pressed = false;
    m_drag_environment = false;
    // The selection's gizmo takes a press on its handles first (gizmo.h); then Ctrl+drag turns
    // the environment; then the lights' handles and markers.
    if (m_drag_button == ImGuiMouseButton_Left && !io.KeyShift && m_drag_pane == 0 &&
        view.mode != ViewMode::lobe &&
        m_gizmo.press(scene, pane_camera(scene), selection, view, m_panes[0].min, m_panes[0].size,
                      press)) {
      m_marker_pressed = true;  // no orbit, no pick
    } else if (m_drag_button == ImGuiMouseButton_Left && io.KeyCtrl &&
               scene.environment.present()) {
      m_drag_environment = true;
    } else if (m_drag_button == ImGuiMouseButton_Left && !io.KeyShift && m_drag_pane >= 0) {
      const Pane& pane = m_panes[m_drag_pane];
      m_drag_aim = aim_handle_at(scene, press);
      if (m_drag_aim >= 0) {
        m_marker_pressed = true;
        selection.light = m_drag_aim;
      }
      for (int i = 0; i < static_cast<int>(scene.lights.size()) && m_drag_aim < 0; ++i) {
        if (scene.lights[i].type == LightType::directional) continue;
        // Hit where it is drawn (light_marker, the same position as draw_light_markers).
        const EdgeMarker m = light_marker(scene, i, pane);
        const float dx = pane.min.x + m.position.x - press.x;
        const float dy = pane.min.y + m.position.y - press.y;
        if (dx * dx + dy * dy <= (kMarkerRadius + 4.0f) * (kMarkerRadius + 4.0f)) {
          // A marker drags its light under the cursor at the light's depth; an off-view arrow
          // pulls its light into view under the cursor (handled with the motion below).
          m_drag_light = i;
          m_drag_off_view = !m.on_screen;
          m_marker_pressed = true;
          selection.light = i;
        }
      }
    }
  }

  const ImVec2 d(io.MousePos.x - m_drag_last.x, io.MousePos.y - m_drag_last.y);
  if (ImGui::IsItemActive() && m_drag_button >= 0 && (d.x != 0.0f || d.y != 0.0f)) {
    m_drag_last = io.MousePos;
    m_drag_distance = std::max(m_drag_distance, std::hypot(io.MousePos.x - m_drag_press.x,
                                                           io.MousePos.y - m_drag_press.y));
    const Pane& pane = m_panes[std::max(m_drag_pane, 0)];
    const bool pan = m_drag_button != ImGuiMouseButton_Left || io.KeyShift;
    if (m_gizmo.dragging()) {
      m_gizmo.drag(commands, io.KeyCtrl, io.MousePos);
    } else if (m_drag_environment) {
      m_marker_pressed = true;  // no pick at the release
      turn_environment(commands, d.x);
    } else if (m_drag_aim >= 0) {
      drag_aim_handle(commands, io.MousePos);
    } else if (m_drag_light >= 0 && m_drag_light < static_cast<int>(scene.lights.size())) {
      const int w = static_cast<int>(pane.size.x), h = static_cast<int>(pane.size.y);
      const Camera camera = pane_camera(scene);
      const glm::vec3& at = scene.lights[m_drag_light].position;
      const glm::vec2 local(io.MousePos.x - pane.min.x, io.MousePos.y - pane.min.y);
      // A marker's light follows the cursor at its own depth; an off-view light, which may sit
      // beside or behind the eye, is brought under the cursor at the depth of the camera's
      // target (the scene's), and follows it there from then on.
      const glm::vec3 moved =
          point_at_depth(camera, w, h, local, m_drag_off_view ? camera.target : at);
      commands.execute(SetField{FieldPart::light, m_drag_light, "position", vec3_value(moved)});
    } else if (m_drag_distance > kClickSlop && !m_marker_pressed) {
      // The scene turns as if grabbed: a drag to the right carries its front to the right (the
      // eye orbits left, positive yaw in orbit_camera); a drag down shows more of its top.
      // Pan at the document camera's scale: its frame's height is the document's view.
      const Camera camera =
          pan ? pan_camera(scene.camera, d.x, d.y,
                           static_cast<int>(m_frames[std::max(m_drag_pane, 0)].size.y))
              : orbit_camera(scene.camera, d.x * kOrbitDegreesPerPixel,
                             d.y * kOrbitDegreesPerPixel);
      commands.execute(SetCamera{camera});
    }
  }

  const RenderSettings& render = scene.render;
  if (ImGui::IsItemHovered() || ImGui::IsItemActive()) {
    int x = 0, y = 0;
    if (render_pixel_at(io.MousePos, render.width, render.height, x, y)) {
      m_hover_x = x;
      m_hover_y = y;
    }
  }

  if (ImGui::IsItemDeactivated()) {
    if (m_drag_button == ImGuiMouseButton_Left && m_drag_light < 0 && !m_marker_pressed &&
        m_drag_distance <= kClickSlop && m_drag_pane >= 0) {
      pin_inspected_pixel(view, render, io.MousePos);
      const Pane& pane = m_panes[m_drag_pane];
      Scene seen = scene;  // meshes are shared: a cheap copy, once per click
      seen.camera = pane_camera(scene);
      const int hit =
          pick_object(seen, static_cast<int>(pane.size.x), static_cast<int>(pane.size.y),
                      io.MousePos.x - pane.min.x, io.MousePos.y - pane.min.y);
      if (hit >= 0) select_only(selection, hit);
    }
    m_drag_button = -1;
    m_drag_light = -1;
    m_drag_aim = -1;
    m_drag_environment = false;
    m_gizmo.release();
  }

  if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f) {
    commands.execute(SetCamera{zoom_camera(scene.camera, io.MouseWheel)});
    m_last_wheel_s = now_s;
  }
}

}  // namespace gloss

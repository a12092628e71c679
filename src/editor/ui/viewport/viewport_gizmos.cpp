// The viewport's handles of directional and spot lights (editor/model/view/light_gizmo.h): a
// directional light's arrow across the scene, a spot's cone, each with an aim handle that turns
// the light when dragged; and Ctrl+drag on the image turning the environment.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "editor/model/view/camera_controller.h"
#include "editor/model/view/light_gizmo.h"
#include "editor/ui/parts/commands.h"
#include "editor/ui/parts/selection.h"
#include "editor/ui/viewport/viewport.h"

namespace gloss {

namespace {

constexpr float kHandleRadius = 6.0f;  // screen pixels
constexpr float kEnvironmentDegreesPerPixel = 0.25f;

ImU32 light_colour(const Light& light, float alpha) {
  const glm::vec3 c = glm::clamp(light.diffuse, glm::vec3(0.0f), glm::vec3(1.0f));
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c.x, c.y, c.z, alpha));
}

}  // namespace

void Viewport::draw_light_gizmos(const Scene& scene, const Selection& selection,
                                 ImDrawList* list) const {
  const Camera camera = pane_camera(scene);
  for (int p = 0; p < m_pane_count; ++p) {
    const Pane& pane = m_panes[p];
    const int w = static_cast<int>(pane.size.x), h = static_cast<int>(pane.size.y);
    auto screen = [&](const glm::vec3& world, ImVec2& out) {
      glm::vec2 px;
      if (!project_point(camera, w, h, world, px)) return false;
      out = ImVec2(pane.min.x + px.x, pane.min.y + px.y);
      return true;
    };
    list->PushClipRect(pane.min, ImVec2(pane.min.x + pane.size.x, pane.min.y + pane.size.y), true);
    for (int i = 0; i < static_cast<int>(scene.lights.size()); ++i) {
      const Light& light = scene.lights[i];
      const LightGizmo g = light_gizmo(light, scene.camera);
      if (!g.aimed) continue;
      const bool selected = i == selection.light;
      const ImU32 line = selected ? IM_COL32(255, 200, 40, 255) : light_colour(light, 0.9f);
      const float thickness = selected ? 2.5f : 1.5f;
      ImVec2 handle;
      const bool handle_shown = screen(g.handle, handle);
      if (light.type == LightType::directional) {
        // The arrow: from the handle to the target, its head where the light arrives.
        ImVec2 head;
        if (handle_shown && screen(scene.camera.target, head)) {
          list->AddLine(handle, head, IM_COL32(0, 0, 0, 200), thickness + 2.0f);
          list->AddLine(handle, head, line, thickness);
          const float dx = head.x - handle.x, dy = head.y - handle.y;
          const float len = std::hypot(dx, dy);
          if (len > 1.0f) {
            const ImVec2 u(dx / len, dy / len), n(-u.y, u.x);
            const float s = 12.0f;
            list->AddTriangleFilled(
                head, ImVec2(head.x - u.x * s + n.x * s * 0.5f, head.y - u.y * s + n.y * s * 0.5f),
                ImVec2(head.x - u.x * s - n.x * s * 0.5f, head.y - u.y * s - n.y * s * 0.5f), line);
          }
        }
      } else {
        // The cone: its rim at the handle (a circle about the axis) and four lines to the apex.
        ImVec2 apex;
        if (screen(g.position, apex)) {
          const glm::vec3 a =
              std::abs(g.direction.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
          const glm::vec3 e1 = glm::normalize(glm::cross(g.direction, a));
          const glm::vec3 e2 = glm::cross(g.direction, e1);
          constexpr int kRim = 32;
          ImVec2 rim[kRim];
          bool all = true;
          for (int k = 0; k < kRim; ++k) {
            const float t = 6.2831853f * static_cast<float>(k) / kRim;
            all =
                screen(g.handle + g.cone_radius * (std::cos(t) * e1 + std::sin(t) * e2), rim[k]) &&
                all;
          }
          if (all) {
            list->AddPolyline(rim, kRim, line, ImDrawFlags_Closed, thickness);
            for (int k = 0; k < kRim; k += kRim / 4) list->AddLine(apex, rim[k], line, thickness);
          }
          if (handle_shown) list->AddLine(apex, handle, line, 1.0f);
        }
      }
      if (handle_shown) {
        list->AddCircleFilled(handle, kHandleRadius, light_colour(light, 1.0f));
        list->AddCircle(handle, kHandleRadius + 1.5f,
                        selected ? IM_COL32(255, 200, 40, 255) : IM_COL32(20, 20, 20, 255), 0,
                        2.0f);
        if (light.type == LightType::directional) {
          char label[48];
          std::snprintf(label, sizeof label, light.follow_camera ? "%d headlight" : "%d", i);
          list->AddText(ImVec2(handle.x + kHandleRadius + 3.0f, handle.y - kHandleRadius - 6.0f),
                        IM_COL32(255, 230, 150, 255), label);
        }
      }
    }
    list->PopClipRect();
  }
}

int Viewport::aim_handle_at(const Scene& scene, ImVec2 press) const {
  if (m_drag_pane < 0) return -1;
  const Pane& pane = m_panes[m_drag_pane];
  const Camera camera = pane_camera(scene);
  for (int i = static_cast<int>(scene.lights.size()) - 1; i >= 0; --i) {
    const LightGizmo g = light_gizmo(scene.lights[i], scene.camera);
    glm::vec2 px;
    if (!g.aimed || !project_point(camera, static_cast<int>(pane.size.x),
                                   static_cast<int>(pane.size.y), g.handle, px)) {
      continue;
    }
    const float dx = pane.min.x + px.x - press.x, dy = pane.min.y + px.y - press.y;
    if (dx * dx + dy * dy <= (kHandleRadius + 4.0f) * (kHandleRadius + 4.0f)) return i;
  }
  return -1;
}

void Viewport::drag_aim_handle(Commands& commands, ImVec2 mouse) const {
  const Scene& scene = commands.scene();
  if (m_drag_aim < 0 || m_drag_aim >= static_cast<int>(scene.lights.size())) return;
  const Pane& pane = m_panes[std::max(m_drag_pane, 0)];
  const Light& light = scene.lights[m_drag_aim];
  const LightGizmo g = light_gizmo(light, scene.camera);
  const glm::vec3 p = point_at_depth(
      pane_camera(scene), static_cast<int>(pane.size.x), static_cast<int>(pane.size.y),
      glm::vec2(mouse.x - pane.min.x, mouse.y - pane.min.y), g.handle);
  commands.execute(SetField{FieldPart::light, m_drag_aim, "direction",
                            vec3_value(direction_for_handle(light, scene.camera, p))});
}

void Viewport::turn_environment(Commands& commands, float dx_px) const {
  const Scene& scene = commands.scene();
  if (!scene.environment.present()) return;
  // The map follows the cursor: a drag to the right turns it clockwise seen from above.
  float degrees = scene.environment.rotation - dx_px * kEnvironmentDegreesPerPixel;
  degrees = std::remainder(degrees, 360.0f);
  FieldValue value;
  value.x = degrees;
  commands.execute(SetField{FieldPart::environment, 0, "rotation", value});
}

}  // namespace gloss

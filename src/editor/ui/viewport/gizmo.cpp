#include "editor/ui/viewport/gizmo.h"

#include <cmath>
#include <cstdio>
#include <vector>

#include "editor/model/view/camera_controller.h"
#include "editor/ui/parts/commands.h"
#include "editor/ui/parts/selection.h"

namespace gloss {

namespace {

const ImU32 kAxisColours[3] = {IM_COL32(232, 72, 72, 255), IM_COL32(112, 204, 72, 255),
                               IM_COL32(72, 128, 240, 255)};
const ImU32 kHot = IM_COL32(255, 214, 60, 255);
const GizmoHandle kAxes[3] = {GizmoHandle::x, GizmoHandle::y, GizmoHandle::z};
const GizmoHandle kPlanes[3] = {GizmoHandle::xy, GizmoHandle::yz, GizmoHandle::zx};

struct Pane {
  ImVec2 min, size;
  int w() const { return static_cast<int>(size.x); }
  int h() const { return static_cast<int>(size.y); }
};

bool to_screen(const Camera& camera, const Pane& pane, const glm::vec3& p, ImVec2& out) {
  glm::vec2 at;
  if (!project_point(camera, pane.w(), pane.h(), p, at)) return false;
  out = ImVec2(pane.min.x + at.x, pane.min.y + at.y);
  return true;
}

ImU32 with_alpha(ImU32 colour, int alpha) {
  return (colour & ~IM_COL32_A_MASK) | (static_cast<ImU32>(alpha) << IM_COL32_A_SHIFT);
}

// Visible selected objects' indices; the gizmo is for them all.
std::vector<int> gizmo_objects(const Scene& scene, const Selection& selection) {
  return selected_objects(selection, static_cast<int>(scene.objects.size()));
}

}  // namespace

bool ViewportGizmo::press(const Scene& scene, const Camera& camera, const Selection& selection,
                          const ViewSettings& view, ImVec2 pane_min, ImVec2 pane_size, ImVec2 p) {
  m_dragging = false;
  const std::vector<int> objects = gizmo_objects(scene, selection);
  if (!view.show_gizmo || objects.empty()) return false;
  const Pane pane{pane_min, pane_size};
  const GizmoFrame frame = gizmo_frame(scene, camera, objects, view.gizmo, pane.w(), pane.h());
  const glm::vec2 local(p.x - pane_min.x, p.y - pane_min.y);
  const GizmoHandle handle = gizmo_hit(camera, pane.w(), pane.h(), frame, view.gizmo, local);
  if (handle == GizmoHandle::none) return false;
  m_drag = GizmoDrag{};
  m_drag.mode = view.gizmo;
  m_drag.handle = handle;
  m_drag.frame = frame;
  m_drag.objects = objects;
  for (int i : objects) {
    const Object& o = scene.objects[static_cast<std::size_t>(i)];
    m_drag.starts.push_back(o.transform);
    m_drag.spheres.push_back(o.type == ObjectType::sphere);
  }
  m_drag.press = local;
  m_pane_min = pane_min;
  m_pane_size = pane_size;
  m_camera = camera;
  m_amount = glm::vec3(m_drag.mode == GizmoMode::scale ? 1.0f : 0.0f, 0.0f, 0.0f);
  m_dragging = true;
  return true;
}

void ViewportGizmo::drag(Commands& commands, bool snap, ImVec2 p) {
  if (!m_dragging) return;
  const Scene& scene = commands.scene();
  for (int i : m_drag.objects) {
    if (i >= static_cast<int>(scene.objects.size())) {  // the scene changed under the drag
      m_dragging = false;
      return;
    }
  }
  const glm::vec2 local(p.x - m_pane_min.x, p.y - m_pane_min.y);
  const std::vector<ObjectTransform> transforms =
      gizmo_transforms(m_camera, static_cast<int>(m_pane_size.x), static_cast<int>(m_pane_size.y),
                       m_drag, local, snap, &m_amount);
  m_snapped = snap;
  commands.execute(TransformObjects{m_drag.objects, transforms});
}

void ViewportGizmo::draw(const Scene& scene, const Camera& camera, const Selection& selection,
                         const ViewSettings& view, ImVec2 pane_min, ImVec2 pane_size, ImVec2 cursor,
                         ImDrawList* list) const {
  const std::vector<int> objects = gizmo_objects(scene, selection);
  if (!view.show_gizmo || objects.empty() || view.mode == ViewMode::lobe) return;
  const Pane pane{pane_min, pane_size};
  const GizmoMode mode = m_dragging ? m_drag.mode : view.gizmo;
  const GizmoFrame f = gizmo_frame(scene, camera, objects, mode, pane.w(), pane.h());
  ImVec2 c;
  if (!f.visible || !to_screen(camera, pane, f.centre, c)) return;
  const GizmoHandle hot = m_dragging
                              ? m_drag.handle
                              : gizmo_hit(camera, pane.w(), pane.h(), f, mode,
                                          glm::vec2(cursor.x - pane_min.x, cursor.y - pane_min.y));
  list->PushClipRect(pane_min, ImVec2(pane_min.x + pane_size.x, pane_min.y + pane_size.y), true);
  if (mode == GizmoMode::rotate) {
    for (int a = 0; a < 3; ++a) {
      std::vector<ImVec2> points;
      for (const glm::vec3& q : gizmo_ring(f, a, 64)) {
        ImVec2 s;
        if (to_screen(camera, pane, q, s)) points.push_back(s);
      }
      const bool h = hot == kAxes[a];
      list->AddPolyline(points.data(), static_cast<int>(points.size()), h ? kHot : kAxisColours[a],
                        ImDrawFlags_Closed, h ? 3.5f : 2.5f);
    }
  } else {
    if (mode == GizmoMode::move) {  // the plane squares, under the axes
      for (int p = 0; p < 3; ++p) {
        const int i = p, j = (p + 1) % 3;
        const float a = 0.25f * f.world_length, b = 0.45f * f.world_length;
        const glm::vec3 corners[4] = {
            f.centre + f.axes[i] * a + f.axes[j] * a, f.centre + f.axes[i] * b + f.axes[j] * a,
            f.centre + f.axes[i] * b + f.axes[j] * b, f.centre + f.axes[i] * a + f.axes[j] * b};
        ImVec2 s[4];
        bool ok = true;
        for (int k = 0; k < 4; ++k) ok = ok && to_screen(camera, pane, corners[k], s[k]);
        if (!ok) continue;
        const ImU32 colour = hot == kPlanes[p] ? kHot : kAxisColours[(p + 2) % 3];
        list->AddQuadFilled(s[0], s[1], s[2], s[3],
                            with_alpha(colour, hot == kPlanes[p] ? 170 : 90));
        list->AddQuad(s[0], s[1], s[2], s[3], colour, 1.0f);
      }
    }
    for (int a = 0; a < 3; ++a) {
      ImVec2 tip;
      if (!to_screen(camera, pane, f.centre + f.axes[a] * f.world_length, tip)) continue;
      const bool h = hot == kAxes[a];
      const ImU32 colour = h ? kHot : kAxisColours[a];
      list->AddLine(c, tip, colour, h ? 4.0f : 3.0f);
      const float dx = tip.x - c.x, dy = tip.y - c.y, len = std::sqrt(dx * dx + dy * dy);
      if (len < 1.0f) continue;
      const ImVec2 d(dx / len, dy / len), n(-d.y, d.x);
      if (mode == GizmoMode::move) {  // an arrow head
        list->AddTriangleFilled(ImVec2(tip.x + d.x * 12, tip.y + d.y * 12),
                                ImVec2(tip.x + n.x * 6, tip.y + n.y * 6),
                                ImVec2(tip.x - n.x * 6, tip.y - n.y * 6), colour);
      } else {  // a box
        list->AddRectFilled(ImVec2(tip.x - 5, tip.y - 5), ImVec2(tip.x + 5, tip.y + 5), colour);
      }
    }
    const bool h = hot == GizmoHandle::view;
    list->AddCircleFilled(c, 7.0f, h ? kHot : IM_COL32(240, 240, 240, 200));
    list->AddCircle(c, 7.5f, IM_COL32(20, 20, 20, 255), 0, 1.5f);
  }
  if (m_dragging) {
    char text[96];
    const char* snap = m_snapped ? " (snapped)" : "  Ctrl: snap";
    if (m_drag.mode == GizmoMode::move) {
      std::snprintf(text, sizeof text, "move %.3f %.3f %.3f%s", m_amount.x, m_amount.y, m_amount.z,
                    snap);
    } else if (m_drag.mode == GizmoMode::rotate) {
      std::snprintf(text, sizeof text, "rotate %.1f deg%s", m_amount.x, snap);
    } else {
      std::snprintf(text, sizeof text, "scale x%.3f%s", m_amount.x, snap);
    }
    const ImVec2 at(c.x + 14.0f, c.y + 12.0f);
    list->AddText(ImVec2(at.x + 1, at.y + 1), IM_COL32(0, 0, 0, 220), text);
    list->AddText(at, IM_COL32(255, 235, 170, 255), text);
  }
  list->PopClipRect();
}

}  // namespace gloss

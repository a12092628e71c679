#pragma once
// The transform gizmo in the viewport (editor/model/view/gizmo.h has its maths): drawn over the
// selected objects in the image pane, in the mode of view.gizmo (move W, rotate E, scale R), and
// dragged with the left button, Ctrl snapping. Every mouse move of a drag is one TransformObjects
// command for the whole selection; the command layer merges them into one undo step, sealed when
// the button is released.
#include <imgui.h>

#include "editor/model/view/gizmo.h"
#include "editor/model/view/view_settings.h"

namespace gloss {

class Commands;
struct Selection;

class ViewportGizmo {
 public:
  // A press at screen point p in the pane at pane_min of pane_size, which shows the scene
  // through camera: true, and a drag begins, when it hits a handle of the gizmo of the selection.
  bool press(const Scene& scene, const Camera& camera, const Selection& selection,
             const ViewSettings& view, ImVec2 pane_min, ImVec2 pane_size, ImVec2 p);
  bool dragging() const { return m_dragging; }
  // The cursor at p during the drag: the selection's transforms as of now (snap: Ctrl held).
  void drag(Commands& commands, bool snap, ImVec2 p);
  void release() { m_dragging = false; }

  // Draws the gizmo in the pane, the handle under the cursor (or the one dragged) highlighted,
  // and during a drag what it has done so far ("move 1.2 0 0").
  void draw(const Scene& scene, const Camera& camera, const Selection& selection,
            const ViewSettings& view, ImVec2 pane_min, ImVec2 pane_size, ImVec2 cursor,
            ImDrawList* list) const;

 private:
  GizmoDrag m_drag;
  bool m_dragging = false;
  ImVec2 m_pane_min{0, 0}, m_pane_size{0, 0};
  Camera m_camera;           // the pane's at the press
  glm::vec3 m_amount{0.0f};  // what gizmo_transforms reported for the last move
  bool m_snapped = false;
};

}  // namespace gloss

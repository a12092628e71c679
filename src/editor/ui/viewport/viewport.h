#pragma once
// The viewport: the progressive renderer's frames as GL textures, drawn by the display shader
// into an off-screen target that an ImGui window shows, in one of the view modes (one image, the
// 2x2 term sheet, or A/B with a heat map). Owns the renderers; never waits for the ray tracer.
// The raster path (issue 12, editor/gl/raster/raster_renderer.h) renders synchronously on the UI
// thread when view.renderer picks it (viewport_raster.cpp); its frames take the same way to the
// screen.
#include <cstdint>
#include <deque>
#include <memory>
#include <string>

#include <imgui.h>

#include "editor/gl/display_shader.h"
#include "editor/gl/gl_texture.h"
#include "editor/gl/raster/raster_renderer.h"
#include "editor/gl/render_target.h"
#include "editor/model/layout/pane_layout.h"
#include "editor/model/measure/exposure_histogram.h"
#include "editor/model/measure/image_cadence.h"
#include "editor/model/view/ab_compare.h"
#include "editor/model/view/albedo_curves.h"
#include "editor/model/view/automatic_choice.h"
#include "editor/model/view/camera_controller.h"
#include "editor/model/view/reference_preview.h"
#include "editor/model/view/view_settings.h"
#include "editor/ui/viewport/gizmo.h"
#include "engine/progressive_renderer.h"

namespace gloss {

class Commands;
struct InputState;
struct Selection;

// Timing of the path edit -> renderer -> pixels on screen, for the status bar and `stats`: the
// newest delays the image cadence completed (image_cadence.h), animations and drags included.
struct LatencyProbe {
  double first_image_ms = 0.0;  // edit -> first frame of it on screen (any resolution)
  double full_image_ms = 0.0;   // edit -> first full-resolution frame of it on screen
};

// What the lobe view keeps between frames: its albedo curves, computed on workers.
struct LobeViewState {
  AlbedoCurves albedo, overlay_albedo;
};

// One pane of the viewport in screen coordinates (ImGui's, y down).
struct Pane {
  ImVec2 min{0, 0};
  ImVec2 size{0, 0};
};

class Viewport {
 public:
  Viewport();  // needs a current GL context
  ~Viewport();

  // Uploads frames published since the last call. now_s: seconds on the frame clock.
  void upload_frames(double now_s);
  // Hands the document to the renderer(s) when it, the view mode or the render size changed.
  // snapshot: the A side of the snapshot comparison (AbSource::snapshot), may be null.
  void sync(const Scene& document, std::uint64_t revision, const ViewSettings& view,
            const Snapshot* snapshot, double now_s);
  // Draws the viewport window at pos/size (screen coordinates) with its gestures: a drag edits the
  // camera or a light through commands, a click selects, with the inspector open it pins a pixel
  // (view). input: where the buttons went down; now_s: the frame clock.
  void draw(Commands& commands, ViewSettings& view, Selection& selection, const InputState& input,
            const Snapshot* snapshot, double now_s, ImVec2 pos, ImVec2 size);
  // Copies the viewport's image into the window's back buffer (framebuffer_height: the window's
  // in framebuffer pixels); call after clearing it and before ImGui draws on top.
  void blit(int framebuffer_height) const;
  // Call after the swap that showed this frame: completes latency measurements.
  void frame_shown(double now_s);

  // The renderer converged on this revision of the document in this view mode, and its last
  // frame is on screen.
  bool converged_and_shown(std::uint64_t revision, const ViewSettings& view) const;
  // A mouse gesture (drag, recent wheel) is in progress: its commands form one undo step.
  bool gesture_active(double now_s) const;
  // A gesture that moves the camera or a light (not a click): RendererChoice::automatic draws
  // with the raster path meanwhile.
  bool moving_gesture(double now_s) const;

  // The screen point at fractions (fx, fy) of the image pane (the first), as of the last draw.
  ImVec2 image_point(float fx, float fy) const {
    return ImVec2(m_panes[0].min.x + fx * m_panes[0].size.x,
                  m_panes[0].min.y + fy * m_panes[0].size.y);
  }

  // The panes of the last draw (pane_layout.h) and A/B's legend, screen coordinates.
  int pane_count() const { return m_pane_count; }
  const Pane& pane(int i) const { return m_panes[i]; }
  const Pane& legend() const { return m_legend; }
  const Pane& frame(int i) const { return m_frames[i]; }
  // The camera the panes show: the document's, or around it when the panes fill their cells
  // (overscan_camera, camera_controller.h).
  Camera pane_camera(const Scene& scene) const;
  // Light `light`'s marker in pane: where it is drawn and where a click hits it (pixels of the
  // pane, y down).
  EdgeMarker light_marker(const Scene& scene, int light, const Pane& pane) const;

  const RenderedFrame* shown_frame() const { return m_frame_a.get(); }
  // The frame whose images the viewport's (A side's) textures hold, kept alive for a writer.
  std::shared_ptr<const RenderedFrame> shown_images() const { return m_image_a; }
  const RenderedFrame* shown_frame_b() const { return m_frame_b.get(); }
  // Which renderer drew the frame shown on each side: true for the raster path.
  bool shown_raster_a() const { return m_shown_raster_a; }
  bool shown_raster_b() const { return m_shown_raster_b; }

  // viewport_raster.cpp. The raster path's frame of scene at scene.render's size (screenshots
  // while the raster path draws the viewport), or null when the raster path cannot run here.
  // Needs the GL context current (the UI thread).
  std::shared_ptr<const RenderedFrame> render_raster(const Scene& scene,
                                                     const RasterSettings& settings, bool terms);
  // Why the raster path cannot run (its programs failed to build), once: empty afterwards and
  // when it runs.
  std::string take_raster_notice();
  bool raster_unavailable() const { return m_raster_failed; }
  // RendererChoice::automatic's figures for a drag of the current setup (automatic_choice.h):
  // which renderer it takes, each renderer's edit -> full-size image delay in drags, and the
  // ray tracer's re-trace at rest (ms, -1 when not measured).
  struct AutomaticReport {
    bool raster = true;
    double raster_ms = -1.0, ray_traced_ms = -1.0, ray_traced_pass_ms = -1.0;
  };
  AutomaticReport automatic_report() const;
  const LatencyProbe& latency() const { return m_latency; }
  // New images on screen and the edit delays, per window (`stats` restarts it).
  const ImageCadence& cadence() const { return m_cadence; }
  void restart_cadence(double now_s) { m_cadence.restart(now_s); }
  // The pixel of the document's render size under the cursor as of the last draw (the pixel
  // inspector's), -1 when the cursor is over no image pane.
  int hover_x() const { return m_hover_x; }
  int hover_y() const { return m_hover_y; }
  float max_difference() const { return m_max_difference; }
  // Counts texture uploads: a new value means a new image reached the screen.
  std::uint64_t uploads() const { return m_uploads; }
  // Bytes of the published frames the viewport holds and of its GL textures (llvmpipe keeps
  // textures in RAM; a GPU driver keeps them in video memory), for the `memory` script line.
  std::uint64_t frame_bytes() const;
  std::uint64_t texture_bytes() const;

  // The histogram of the live image as shown (the total, or the single term shown; in the
  // snapshot A/B the live B side), recomputed only when that image or the display changed.
  // Large images are sampled (every step-th pixel and row, at most ~16k pixels) to stay well
  // under a millisecond; exact=true counts every pixel (the `stats` line).
  ExposureHistogram histogram(const ViewSettings& view, const DisplayTransform& display,
                              bool exact = false);

 private:
  // Drops the edits waiting for an image (the image cadence's and the drag tags): their frames
  // would come from a renderer whose generations no longer compare (a new one, or the other side).
  void forget_edits();
  // viewport_input.cpp: gestures, light markers, picking.
  void handle_input(Commands& commands, ViewSettings& view, Selection& selection,
                    const InputState& input, double now_s);
  void draw_light_markers(const Scene& scene, const Selection& selection, ImDrawList* list) const;
  // viewport_gizmos.cpp: directional and spot lights' arrows, cones and aim handles; the
  // environment turned by Ctrl+drag.
  void draw_light_gizmos(const Scene& scene, const Selection& selection, ImDrawList* list) const;
  int aim_handle_at(const Scene& scene, ImVec2 press) const;  // light index or -1
  void drag_aim_handle(Commands& commands, ImVec2 mouse) const;
  void turn_environment(Commands& commands, float dx_px) const;
  int pane_at(ImVec2 screen) const;  // -1: over no image pane
  // The pixel of the document's render size (width x height) under screen point p in an image
  // pane (not the A/B legend); false outside them.
  bool render_pixel_at(ImVec2 p, int width, int height, int& x, int& y) const;
  void draw_inspected_pixel(const ViewSettings& view, const RenderSettings& render,
                            ImDrawList* list) const;
  void pin_inspected_pixel(ViewSettings& view, const RenderSettings& render, ImVec2 p) const;

  void draw_panes(const ViewSettings& view, const DisplayTransform& display);  // the document's
  void draw_labels(const ViewSettings& view, ImDrawList* list) const;
  void draw_legend(const ViewSettings& view, ImDrawList* list, const Pane& pane) const;
  void upload(const RenderedFrame& frame, bool b_side);
  void max_difference_of_shown();

  // viewport_raster.cpp: the raster path.
  // Whether view wants the raster path for the viewport's own renderer now (gl, or automatic
  // during a moving gesture) and it can run.
  bool raster_effective(const ViewSettings& view, double now_s);
  bool raster_available();  // builds the renderer on first use; false when that failed
  // Renders the raster sides of a (and b in the A/B view) and shows them; false when render()
  // threw (the message goes to the notice).
  bool show_raster(const AbScenes& scenes, const AbSides& sides, const RasterSettings& settings,
                   bool terms, bool ab, double now_s);
  static void reset_gl_state();  // what the display shader and ImGui expect after a raster pass

  // Null while the raster path draws the A side, but paused during an Automatic drag.
  std::unique_ptr<ProgressiveRenderer> m_a;
  std::unique_ptr<ProgressiveRenderer> m_b;  // B side of the A/B view when the ray tracer draws it
  // B side of the material | reference A/B view: the physical reference (AbSide::physical).
  std::unique_ptr<ReferencePreview> m_reference;
  std::shared_ptr<const RenderedFrame> m_frame_a, m_frame_b;
  std::shared_ptr<const RenderedFrame> m_image_a, m_image_b;  // the newest with a total image

  GlTexture m_total, m_emissive, m_ambient, m_diffuse, m_specular, m_b_total;
  RenderTarget m_target;
  DisplayShader m_shader;

  // What the renderers were last given, and the generations set_scene last returned.
  std::uint64_t m_last_generation_a = 0, m_last_generation_b = 0;
  std::uint64_t m_pushed_revision = 0;
  bool m_pushed_any = false;
  int m_render_width = 0, m_render_height = 0;
  ViewMode m_pushed_mode = ViewMode::render;
  bool m_pushed_terms = false;
  bool m_pushed_keep = false;
  AbSource m_pushed_source = AbSource::models;
  std::uint64_t m_pushed_snapshot = 0;  // revision of the snapshot pushed as A
  bool m_pushed_uv_checker = false;     // the renderers were handed the UV checker view
  std::string m_label_a, m_label_b;     // A/B pane labels of what was pushed
  AbSides m_sides;                      // which renderer draws each side (A alone outside A/B)
  RendererChoice m_pushed_renderer = RendererChoice::cpu;
  RasterSettings m_pushed_raster;

  // The raster path: built on the UI thread when first needed.
  std::unique_ptr<RasterRenderer> m_raster;
  bool m_raster_failed = false;     // its constructor threw: the ray tracer draws every side
  std::string m_raster_notice;      // a failure, until take_raster_notice() hands it out
  std::string m_raster_last_error;  // the last render failure announced (no repeats)
  // What the shown raster frames were rendered from; a new render only when it changes.
  struct RasterKey {
    std::uint64_t revision = 0, snapshot = 0;
    int width = 0, height = 0;
    bool terms = false, ab = false, keep = false;
    AbSource source = AbSource::models;
    AbSides sides;
    RasterSettings settings;
    std::size_t lights = 0;   // the document's light count (the raster path takes 32 at most)
    bool uv_checker = false;  // the UV checker view: the same revision, other materials
    bool operator==(const RasterKey& o) const;
    // Equal but perhaps for the document's revision and the snapshot's: what a failure that
    // does not depend on the edit (too many lights, shadow maps too large) repeats on.
    bool same_setup(const RasterKey& o) const;
  };
  RasterKey m_raster_key;
  // Automatic's measurements: m_setup is the setup of the newest sync (what a drag now would
  // draw), m_traced_setup what the A side's ray tracer was last handed.
  AutomaticChoice m_automatic;
  DragSetup m_setup, m_traced_setup;
  // The generation of the scene handed to the ray tracer when it took A over from the raster
  // path: its older frames (a paused renderer's) are not shown.
  std::uint64_t m_handover_generation = 0;
  bool m_raster_shown = false;  // m_raster_key describes frames on screen
  // render() threw for m_raster_key (too many lights, shadow maps too large, a GL error): the
  // ray tracer draws; the raster path is tried again when the setup changes (same_setup), not
  // on every edit of a drag.
  bool m_raster_render_failed = false;
  bool m_shown_raster_a = false, m_shown_raster_b = false;

  // Layout of the last draw (screen coordinates).
  ImVec2 m_pos{0, 0}, m_size{0, 0};
  float m_framebuffer_scale = 1.0f;
  bool m_visible = false;  // the viewport window was drawn this frame (blit() shows it)
  Pane m_panes[4];
  Pane m_frames[4];  // the document's frame in each pane (pane_layout.h)
  int m_pane_count = 1;
  bool m_fill = false;  // the panes fill their cells: rendered through pane_camera()
  Pane m_legend;        // A/B's heat-map legend, beside the panes (pane_layout.h)

  float m_max_difference = 0.0f;  // largest |A - B| of the shown pair, linear

  // What the off-screen target last showed: it is redrawn only when one of these changes, so an
  // idle frame costs ImGui's draw alone (llvmpipe samples float textures slowly).
  struct TargetKey {
    std::uint64_t uploads = 0;
    int width = 0, height = 0, pane_count = 0;
    float pane_x = 0, pane_y = 0, pane_w = 0, pane_h = 0;
    ViewMode mode = ViewMode::render;
    TermView single = TermView::total;
    float gain = 0, heat_scale = 0;
    ToneCurve tone = ToneCurve::none;
    bool srgb = false;
    bool show_clipped = false;
    bool operator==(const TargetKey& o) const;
  };
  TargetKey m_target_key;
  std::uint64_t m_uploads = 0;  // counts texture uploads
  LatencyProbe m_latency;
  ImageCadence m_cadence;
  // An image uploaded this frame, for the swap that shows it: its generation (kNewest: the
  // raster path's, of the newest edit) and whether it has the render's size.
  bool m_show_pending = false;
  std::uint64_t m_show_generation = 0;
  bool m_show_full = false;
  // The edits not shown yet: whether each came from a drag, and its setup (Automatic files a
  // drag's delay under the setup of its edit).
  struct EditTag {
    std::uint64_t generation;
    bool drag;
    DragSetup setup;
  };
  std::deque<EditTag> m_edit_tags;
  bool m_watch_b = false;  // the newest edit changed the B side alone (A/B snapshot | live)
  LobeViewState m_lobe;    // the lobe view's (lobe_view.cpp)

  // The last histogram (histogram()) and what it was computed from.
  struct HistogramKey {
    const void* frame = nullptr;
    float gain = 0.0f;
    ToneCurve tone = ToneCurve::none;
    bool srgb = false, exact = false;
    TermView term = TermView::total;
    bool operator==(const HistogramKey& o) const {
      return frame == o.frame && gain == o.gain && tone == o.tone && srgb == o.srgb &&
             exact == o.exact && term == o.term;
    }
  };
  HistogramKey m_histogram_key;
  ExposureHistogram m_histogram;

  // Gesture state (viewport_input.cpp).
  ViewportGizmo m_gizmo;            // the selection's transform gizmo and its drag (gizmo.h)
  int m_drag_button = -1;           // ImGuiMouseButton being dragged in the viewport, -1 none
  int m_drag_light = -1;            // light being dragged, -1 none
  bool m_drag_off_view = false;     // ... by its off-view arrow: brought to the target's depth
  int m_drag_aim = -1;              // light whose aim handle is dragged, -1 none
  bool m_drag_environment = false;  // Ctrl+drag: turning the environment
  bool m_marker_pressed = false;    // the press hit a light marker (no orbit, no pick)
  int m_drag_pane = 0;
  float m_drag_distance = 0.0f;  // farthest the cursor went from the press, pixels
  ImVec2 m_drag_press{0, 0};     // where the drag's button went down (screen)
  ImVec2 m_drag_last{0, 0};      // cursor position the drag has consumed up to
  double m_last_wheel_s = -1.0;
  int m_hover_x = -1, m_hover_y = -1;  // render pixel under the cursor (hover_x)
};

// lobe_view.cpp: the lobe view of the selected object's material, drawn by the viewport in its
// place when view.mode is ViewMode::lobe; dragging in the plot moves the view's light. snapshot:
// the A/B snapshot (the second material it may draw), may be null.
void draw_lobe_view(const Scene& scene, const Selection& selection, ViewSettings& view,
                    const Snapshot* snapshot, LobeViewState& state, ImVec2 pos, ImVec2 size);

}  // namespace gloss

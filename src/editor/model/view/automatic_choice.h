#pragma once
// RendererChoice::automatic's decision for drags (issue 12, Speed): a drag of the camera or a
// light goes to the raster path only where its images reach the screen no later than the ray
// tracer's would. On a GPU the raster frame is a fraction of the re-trace and every drag goes to
// it; on a software rasterizer (llvmpipe) it depends on the scene, the size and how busy the
// cores are (docs/accuracy.md, "Speed"), so it is measured in place, in the editor, where the
// ray tracer shares the cores with the UI.
//
// The figure compared is the viewport's edit -> full-size image delay during drags (the status
// bar's "full res"), for each renderer. For a camera drag the ray tracer's full-size re-trace at
// rest is a lower bound of its delay (each edit re-traces): a raster delay at or under it needs
// no further proof. Otherwise, and always for a light drag (the ray tracer only re-lights, which
// can be cheaper than a re-trace), one drag is given to the ray tracer to measure its delay, and
// the faster renderer takes the drags.
//
// GL-free: the viewport reports the measurements (viewport.h) and asks here.
#include <cstddef>
#include <vector>

#include "editor/model/view/raster_settings.h"
#include "scene/scene.h"

namespace gloss {

// What a frame's cost depends on. Figures are compared only between equal setups.
struct DragSetup {
  int width = 0, height = 0;   // render size, pixels
  bool terms = false;          // the four term images as well as the total
  bool ab = false;             // the A/B view (two images per frame)
  bool shadows = false;        // render.shadows with at least one light
  std::size_t lights = 0;      // point lights
  std::size_t primitives = 0;  // mesh triangles plus spheres
  RasterSettings raster;       // raster knobs (its shading frequency included)
  bool light_drag = false;     // a light drag: shadow maps redrawn, the ray tracer re-lights

  bool same_image(const DragSetup& o) const;   // all but the raster knobs and the drag kind
  bool same_drag(const DragSetup& o) const;    // same_image and the drag kind
  bool same_raster(const DragSetup& o) const;  // same_drag and the raster knobs
};

// The setup of scene drawn at width x height in the given view.
DragSetup drag_setup(const Scene& scene, int width, int height, bool terms, bool ab,
                     const RasterSettings& raster, bool light_drag);

class AutomaticChoice {
 public:
  // An edit made during a drag reached the screen as a full-size image ms after it, drawn by the
  // raster path (raster) or the ray tracer. The raster path's first image of a setup is not
  // counted: it may carry program builds and the first shadow maps.
  void drag_image(const DragSetup& setup, bool raster, double ms);
  // The ray tracer finished a full-size 1-spp re-trace of setup in ms (pass time). The first of
  // a setup is not counted: a new renderer's or a new size's first pass fills fresh caches.
  void ray_traced_pass(const DragSetup& setup, double ms);
  // The viewport made a new ray tracer: its first pass is cold again.
  void ray_tracer_restarted();

  // Whether a drag with setup goes to the raster path. Decided once per setup, on the first
  // figures that settle it (possibly within a drag: the ray tracer's timing drag ends on the
  // raster path when that one proves faster), and kept: later frames do not flip it.
  bool raster_for(const DragSetup& setup);
  // What raster_for would answer, without deciding (the status bar's and `stats`' report).
  bool would_raster(const DragSetup& setup) const;

  // The figures, ms, -1 when not measured; once decided, the ones it was decided on.
  double raster_ms(const DragSetup& setup) const;           // raster drag delay
  double ray_traced_ms(const DragSetup& setup) const;       // ray tracer's drag delay
  double ray_traced_pass_ms(const DragSetup& setup) const;  // its re-trace at rest

 private:
  struct Decision {
    DragSetup setup;
    bool raster = true;
    double raster_ms = -1.0, traced_ms = -1.0, pass_ms = -1.0;  // what it was decided on
  };
  // The decision for setup, or null. A few are kept (camera and light drags, a size or two), the
  // oldest dropped first.
  const Decision* decision(const DragSetup& setup) const;
  // The rule, in one place: which renderer, and whether the figures settle it.
  struct Verdict {
    bool raster = true, settled = false;
  };
  Verdict verdict(const DragSetup& setup) const;

  // One measured figure: the setups it holds for (same), the setup it was measured for, how
  // many were seen and the newest counted, ms (-1: none yet).
  struct Figure {
    bool (DragSetup::*same)(const DragSetup&) const;
    bool skip_first;  // a setup's first is cold (program builds, fresh caches): not counted
    DragSetup setup;
    int count = 0;
    double ms = -1.0;
    void take(const DragSetup& s, double measured_ms);
    double for_setup(const DragSetup& s) const { return (s.*same)(setup) ? ms : -1.0; }
  };
  Figure m_raster{&DragSetup::same_raster, true, {}};  // raster drag delay
  Figure m_traced{&DragSetup::same_drag, false, {}};   // ray tracer's drag delay
  Figure m_pass{&DragSetup::same_image, true, {}};     // its re-trace at rest
  std::vector<Decision> m_decisions;                   // newest last
};

}  // namespace gloss

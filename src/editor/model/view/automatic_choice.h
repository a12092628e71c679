#pragma once
// RendererChoice::automatic's decision for drags (issue 12, Speed): the raster path draws a
// drag of the camera or a light only where it was measured to be no slower than the ray
// tracer's full-size 1-spp pass of the same image. On a GPU the raster frame is a fraction of
// the re-trace and every drag goes to it; on a software rasterizer (llvmpipe, docs/accuracy.md)
// a frame with shadow maps costs about 1.4 re-traces, and a drag that would be slower stays
// with the ray tracer, so Automatic never makes dragging slower than the ray tracer alone.
//
// GL-free: the viewport reports each renderer's frame times (viewport.h) and asks here.
#include <cstddef>

#include "editor/model/view/raster_settings.h"
#include "scene/scene.h"

namespace gloss {

// What a frame's cost depends on. Two frames are compared only when their images are the same
// setup (same_image); raster timings are kept per raster setup (same_raster) as well, since the
// shadow-map knobs and a light drag (maps redrawn every frame) change the raster frame alone.
struct DragSetup {
  int width = 0, height = 0;   // render size, pixels
  bool terms = false;          // the four term images as well as the total
  bool ab = false;             // the A/B view (two images per frame)
  bool shadows = false;        // render.shadows with at least one light
  std::size_t lights = 0;      // point lights
  std::size_t primitives = 0;  // mesh triangles plus spheres
  RasterSettings raster;       // raster knobs (its shading frequency included)
  bool light_drag = false;     // a light is being dragged: shadow maps redrawn every frame

  bool same_image(const DragSetup& o) const;
  bool same_raster(const DragSetup& o) const;  // same_image, raster knobs and drag kind
};

// The setup of scene drawn at width x height in the given view.
DragSetup drag_setup(const Scene& scene, int width, int height, bool terms, bool ab,
                     const RasterSettings& raster, bool light_drag);

class AutomaticChoice {
 public:
  // The raster path drew a frame of setup in ms (shadow maps, draw and read-back; not the mesh
  // uploads, which a drag does not repeat). The first frame of a setup is not counted: it may
  // carry program builds and the first shadow maps.
  void raster_frame(const DragSetup& setup, double ms);
  // The ray tracer finished a full-size 1-spp pass after a restart (a re-trace) of setup in ms.
  // The first of a setup is not counted either: a new renderer's or a new size's first pass
  // fills fresh caches (37 ms against 16 ms warm, 691x691 cornell-teapot in the editor here).
  void ray_traced_frame(const DragSetup& setup, double ms);

  // Whether a drag with setup goes to the raster path: yes while either side is unmeasured for
  // it (the raster path's first frames are its measurement); otherwise when the raster frame is
  // no slower. Decided once per setup, so a drag never flips between renderers (each flip
  // rebuilds the ray tracer's scene).
  bool raster_for(const DragSetup& setup);
  // What raster_for would answer, without deciding (the status bar's and `stats`' report).
  bool would_raster(const DragSetup& setup) const;

  // The figures behind raster_for for setup, ms; -1 when not measured.
  double raster_ms(const DragSetup& setup) const;
  double ray_traced_ms(const DragSetup& setup) const;

 private:
  DragSetup m_raster_setup;
  int m_raster_frames = 0;  // frames of m_raster_setup seen, the first not counted
  double m_raster_ms = -1.0;
  DragSetup m_traced_setup;
  int m_traced_frames = 0;
  double m_traced_ms = -1.0;
  // The decision, once both were measured for m_decided_setup.
  DragSetup m_decided_setup;
  bool m_decided = false, m_decided_raster = true;
};

}  // namespace gloss

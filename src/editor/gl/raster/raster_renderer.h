#pragma once
// The raster path (issue 12): the document drawn by OpenGL 3.3 core with the shading contract of
// shaders/phong_contract.glsl in every program. Spheres are ray-cast impostors that write depth
// (silhouettes and normals as the ray tracer's at pixel centres); meshes (quads, boxes, the
// teapot, model files) are the document's own world-space triangles, the CPU path's
// tessellation. One sample per pixel, at the pixel centre. The total and the four term buffers
// go to float render targets and are read back as a RenderedFrame, so every view of the editor
// (terms, A/B, inspector, histogram, screenshots) works on this path as on the ray tracer's.
// Hard shadows: one cube shadow map per light (raster_settings.h: size and bias).
//
// Needs a current GL 3.3 core context on the calling thread (the editor's window, or EGL in
// tests) for its whole life.
#include <functional>
#include <memory>
#include <string>

#include "editor/model/view/raster_settings.h"
#include "engine/progressive_renderer.h"
#include "scene/scene.h"

namespace gloss {

// Where the time of the last render() went, milliseconds of wall time (each phase ends with
// glFinish, so llvmpipe's work is inside it).
struct RasterTiming {
  double upload_ms = 0;    // geometry uploaded (only meshes that changed)
  double shadow_ms = 0;    // shadow maps drawn (0 when reused or shadows are off)
  double draw_ms = 0;      // the scene drawn into the five float targets
  double readback_ms = 0;  // the targets read back into the frame's images
  double total_ms() const { return upload_ms + shadow_ms + draw_ms + readback_ms; }
};

class RasterRenderer {
 public:
  // Applied to every shader's full text before it is compiled. Tests plant errors with it (a
  // wrong attenuation, a missing term) to show that the agreement tests catch them.
  using SourceEdit = std::function<std::string(const std::string&)>;

  // Builds the programs; throws std::runtime_error with the compiler's log when one fails.
  explicit RasterRenderer(SourceEdit edit = {});
  ~RasterRenderer();
  RasterRenderer(const RasterRenderer&) = delete;
  RasterRenderer& operator=(const RasterRenderer&) = delete;

  // Renders scene at scene.render.width x height (spp, sampling and pow are ignored: one sample
  // per pixel, exact pow). terms: read the four term images back too (otherwise only the total).
  // The frame says spp 1, converged, pass_ms = timing().total_ms(). Shadow maps and mesh buffers
  // are kept between calls and redrawn / re-uploaded only when what they depend on changed.
  std::shared_ptr<RenderedFrame> render(const Scene& scene, const RasterSettings& settings,
                                        bool terms);

  const RasterTiming& timing() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace gloss

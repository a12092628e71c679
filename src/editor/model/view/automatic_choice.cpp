#include "editor/model/view/automatic_choice.h"

namespace gloss {

bool DragSetup::same_image(const DragSetup& o) const {
  return width == o.width && height == o.height && terms == o.terms && ab == o.ab &&
         shadows == o.shadows && lights == o.lights && primitives == o.primitives;
}

bool DragSetup::same_raster(const DragSetup& o) const {
  return same_image(o) && raster == o.raster && light_drag == o.light_drag;
}

DragSetup drag_setup(const Scene& scene, int width, int height, bool terms, bool ab,
                     const RasterSettings& raster, bool light_drag) {
  DragSetup s;
  s.width = width;
  s.height = height;
  s.terms = terms;
  s.ab = ab;
  s.lights = scene.lights.size();
  s.shadows = scene.render.shadows && s.lights > 0;
  for (const Object& o : scene.objects) {
    s.primitives += o.mesh ? o.mesh->triangles.size() : 1;
  }
  s.raster = raster;
  s.light_drag = light_drag;
  return s;
}

void AutomaticChoice::raster_frame(const DragSetup& setup, double ms) {
  if (!setup.same_raster(m_raster_setup)) {
    m_raster_setup = setup;
    m_raster_frames = 0;
    m_raster_ms = -1.0;
  }
  if (++m_raster_frames > 1) m_raster_ms = ms;
}

void AutomaticChoice::ray_traced_frame(const DragSetup& setup, double ms) {
  if (!setup.same_image(m_traced_setup)) {
    m_traced_setup = setup;
    m_traced_frames = 0;
    m_traced_ms = -1.0;
  }
  if (++m_traced_frames > 1) m_traced_ms = ms;
}

bool AutomaticChoice::would_raster(const DragSetup& setup) const {
  if (m_decided && setup.same_raster(m_decided_setup)) return m_decided_raster;
  const double raster = raster_ms(setup), traced = ray_traced_ms(setup);
  return raster < 0.0 || traced < 0.0 || raster <= traced;
}

bool AutomaticChoice::raster_for(const DragSetup& setup) {
  const bool raster = would_raster(setup);
  if (!(m_decided && setup.same_raster(m_decided_setup)) && raster_ms(setup) >= 0.0 &&
      ray_traced_ms(setup) >= 0.0) {
    m_decided = true;
    m_decided_setup = setup;
    m_decided_raster = raster;
  }
  return raster;
}

double AutomaticChoice::raster_ms(const DragSetup& setup) const {
  return setup.same_raster(m_raster_setup) ? m_raster_ms : -1.0;
}

double AutomaticChoice::ray_traced_ms(const DragSetup& setup) const {
  return setup.same_image(m_traced_setup) ? m_traced_ms : -1.0;
}

}  // namespace gloss

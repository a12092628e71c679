#include "editor/model/view/automatic_choice.h"

namespace gloss {

bool DragSetup::same_image(const DragSetup& o) const {
  return width == o.width && height == o.height && terms == o.terms && ab == o.ab &&
         shadows == o.shadows && lights == o.lights && primitives == o.primitives;
}

bool DragSetup::same_drag(const DragSetup& o) const {
  return same_image(o) && light_drag == o.light_drag;
}

bool DragSetup::same_raster(const DragSetup& o) const {
  return same_drag(o) && raster == o.raster;
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

namespace {
constexpr std::size_t kKeptDecisions = 8;
}  // namespace

const AutomaticChoice::Decision* AutomaticChoice::decision(const DragSetup& setup) const {
  for (const Decision& d : m_decisions) {
    if (setup.same_raster(d.setup)) return &d;
  }
  return nullptr;
}

void AutomaticChoice::drag_image(const DragSetup& setup, bool raster, double ms) {
  if (decision(setup) != nullptr) return;  // keep the figures it was decided on
  Figure& f = raster ? m_raster : m_traced;
  const bool same = raster ? setup.same_raster(f.setup) : setup.same_drag(f.setup);
  if (!same) f = Figure{setup, 0, -1.0};
  if (++f.count > 1 || !raster) f.ms = ms;
}

void AutomaticChoice::ray_traced_pass(const DragSetup& setup, double ms) {
  if (!setup.same_image(m_pass.setup)) m_pass = Figure{setup, 0, -1.0};
  if (++m_pass.count > 1) m_pass.ms = ms;
}

void AutomaticChoice::ray_tracer_restarted() {
  m_pass.count = 0;  // the figure stays; the next pass is not counted
}

bool AutomaticChoice::would_raster(const DragSetup& setup) const {
  if (const Decision* d = decision(setup)) return d->raster;
  const double raster = raster_ms(setup);
  const double traced = ray_traced_ms(setup);
  const double pass = ray_traced_pass_ms(setup);
  if (raster < 0.0) return true;  // the raster path is timed on a drag first
  if (traced >= 0.0) return raster <= traced;
  if (setup.light_drag) return false;  // no lower bound: one drag times the ray tracer
  if (pass < 0.0) return true;         // nothing known of the ray tracer yet
  return raster <= pass;               // else one drag to time the ray tracer
}

bool AutomaticChoice::raster_for(const DragSetup& setup) {
  const bool raster = would_raster(setup);
  if (decision(setup) == nullptr) {
    const double r = raster_ms(setup), t = ray_traced_ms(setup), p = ray_traced_pass_ms(setup);
    const bool bound = !setup.light_drag && p >= 0.0 && r <= p;
    if (r >= 0.0 && (t >= 0.0 || bound)) {
      if (m_decisions.size() == kKeptDecisions) m_decisions.erase(m_decisions.begin());
      m_decisions.push_back({setup, raster, r, t, p});
    }
  }
  return raster;
}

double AutomaticChoice::raster_ms(const DragSetup& setup) const {
  if (const Decision* d = decision(setup)) return d->raster_ms;
  return setup.same_raster(m_raster.setup) ? m_raster.ms : -1.0;
}

double AutomaticChoice::ray_traced_ms(const DragSetup& setup) const {
  if (const Decision* d = decision(setup)) return d->traced_ms;
  return setup.same_drag(m_traced.setup) ? m_traced.ms : -1.0;
}

double AutomaticChoice::ray_traced_pass_ms(const DragSetup& setup) const {
  if (const Decision* d = decision(setup)) return d->pass_ms;
  return setup.same_image(m_pass.setup) ? m_pass.ms : -1.0;
}

}  // namespace gloss

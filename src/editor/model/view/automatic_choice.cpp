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

void AutomaticChoice::Figure::take(const DragSetup& s, double measured_ms) {
  if (!(s.*same)(setup)) *this = Figure{same, skip_first, s};
  if (++count > 1 || !skip_first) ms = measured_ms;
}

void AutomaticChoice::drag_image(const DragSetup& setup, bool raster, double ms) {
  if (decision(setup) != nullptr) return;  // keep the figures it was decided on
  (raster ? m_raster : m_traced).take(setup, ms);
}

void AutomaticChoice::ray_traced_pass(const DragSetup& setup, double ms) {
  m_pass.take(setup, ms);
}

void AutomaticChoice::ray_tracer_restarted() {
  m_pass.count = 0;  // the figure stays; the next pass is not counted
}

AutomaticChoice::Verdict AutomaticChoice::verdict(const DragSetup& setup) const {
  if (const Decision* d = decision(setup)) return {d->raster, true};
  const double raster = m_raster.for_setup(setup);
  const double traced = m_traced.for_setup(setup);
  const double pass = m_pass.for_setup(setup);
  if (raster < 0.0) return {true, false};  // the raster path is timed on a drag first
  if (traced >= 0.0) return {raster <= traced, true};
  if (setup.light_drag) return {false, false};  // no lower bound: one drag times the ray tracer
  if (pass < 0.0) return {true, false};         // nothing known of the ray tracer yet
  if (raster <= pass) return {true, true};      // within a lower bound of the ray tracer's delay
  return {false, false};                        // one drag to time the ray tracer
}

bool AutomaticChoice::would_raster(const DragSetup& setup) const {
  return verdict(setup).raster;
}

bool AutomaticChoice::raster_for(const DragSetup& setup) {
  const Verdict v = verdict(setup);
  if (v.settled && decision(setup) == nullptr) {
    if (m_decisions.size() == kKeptDecisions) m_decisions.erase(m_decisions.begin());
    m_decisions.push_back({setup, v.raster, m_raster.for_setup(setup), m_traced.for_setup(setup),
                           m_pass.for_setup(setup)});
  }
  return v.raster;
}

double AutomaticChoice::raster_ms(const DragSetup& setup) const {
  const Decision* d = decision(setup);
  return d ? d->raster_ms : m_raster.for_setup(setup);
}

double AutomaticChoice::ray_traced_ms(const DragSetup& setup) const {
  const Decision* d = decision(setup);
  return d ? d->traced_ms : m_traced.for_setup(setup);
}

double AutomaticChoice::ray_traced_pass_ms(const DragSetup& setup) const {
  const Decision* d = decision(setup);
  return d ? d->pass_ms : m_pass.for_setup(setup);
}

}  // namespace gloss

#include "engine/light_preview.h"

#include <algorithm>

#include "engine/trace/single_sample_pass.h"

namespace gloss {

namespace {
// A fresh trace costs more per pixel than a re-light from cached hits (the primary rays as well):
// about 1.5 times on the benchmark scene (retrace_ms against light_move_ms, docs/engine.md); 2
// keeps the preview's estimate on the safe side.
constexpr double kTraceOverRelight = 2.0;
}  // namespace

void LightPreview::light_pass(double ms, bool completed) {
  m_light_ms = completed ? ms : std::max(m_light_ms, ms);
}

int LightPreview::shift(double budget_ms, int max_shift, double trace_ms) const {
  const double expected = m_light_ms >= 0 ? m_light_ms : trace_ms;
  if (budget_ms <= 0 || max_shift <= 0 || expected < 0 || expected <= budget_ms) return 0;
  for (int s = 1; s < max_shift; ++s) {  // a quarter of the pixels per step
    if (expected * kTraceOverRelight / static_cast<double>(1 << (2 * s)) <= budget_ms) return s;
  }
  return max_shift;
}

bool LightPreview::render(const RenderContext& ctx, int width, int height, TermImages& images,
                          bool terms) {
  reset_sample_cache(m_cache, *ctx.scene, width, height, 1);
  if (terms) {
    if (!trace_single_sample(m_cache, ctx, m_factors)) return false;
    combine_terms(m_factors, ctx, images, true);
    return true;
  }
  return trace_single_sample(m_cache, ctx, m_factors, &images.total);
}

}  // namespace gloss

#include "engine/edit_preview.h"

#include <algorithm>

#include "engine/environment/environment_stage.h"
#include "engine/trace/single_sample_pass.h"

namespace gloss {

namespace {
// A fresh trace costs more per pixel than a re-light from cached hits (the primary rays as well):
// about 1.5 times on the benchmark scene (retrace_ms against light_move_ms, docs/engine.md), and
// more than a re-shade or re-summing of the cosines; 2 keeps the estimate on the safe side.
constexpr double kTraceOverPass = 2.0;

// The slot of a class in EditPreview::m_pass_ms, -1 for classes without a preview.
int slot(ChangeClass change) {
  switch (change) {
    case ChangeClass::shade:
      return 0;
    case ChangeClass::exponent:
      return 1;
    case ChangeClass::light:
      return 2;
    default:
      return -1;
  }
}
}  // namespace

void EditPreview::first_pass(ChangeClass change, double ms, bool completed) {
  const int s = slot(change);
  if (s < 0) return;
  m_pass_ms[s] = completed ? ms : std::max(m_pass_ms[s], ms);
}

int EditPreview::shift(ChangeClass change, double budget_ms, int max_shift, double trace_ms) const {
  const int s = slot(change);
  if (s < 0) return 0;
  const double expected =
      m_pass_ms[s] >= 0 ? m_pass_ms[s] : (change == ChangeClass::light ? trace_ms : -1);
  if (budget_ms <= 0 || max_shift <= 0 || expected < 0 || expected <= budget_ms) return 0;
  for (int k = 1; k < max_shift; ++k) {  // a quarter of the pixels per step
    if (expected * kTraceOverPass / static_cast<double>(1 << (2 * k)) <= budget_ms) return k;
  }
  return max_shift;
}

bool EditPreview::render(const RenderContext& ctx, int width, int height, TermImages& images,
                         bool terms) {
  reset_sample_cache(m_cache, *ctx.scene, width, height, 1);
  // The environment's sky comes after the factors (combine_terms adds it).
  const bool sky = ctx.plan.sky && ctx.scene->environment.as_background;
  if (terms || sky) {
    if (!trace_single_sample(m_cache, ctx, m_factors)) return false;
    if (ctx.plan.sky && !environment_sky(m_cache, ctx, m_factors)) return false;
    combine_terms(m_factors, ctx, images, terms);
    return true;
  }
  return trace_single_sample(m_cache, ctx, m_factors, &images.total);
}

}  // namespace gloss

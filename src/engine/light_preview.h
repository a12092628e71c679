#pragma once
// A light edit's first image when the machine cannot re-light the full image quickly: while a
// full-resolution light pass is expected to take longer than a budget
// (ProgressiveOptions::light_preview_budget_ms), the progressive engine first shows the edit as
// a coarse image (a fresh 1-spp trace at 1/2, 1/4 or 1/8 resolution, the finest expected within
// the budget) traced into a cache of its own, so the full-resolution cache keeps its hits for the
// re-light that follows. Under continuous light edits on a loaded machine (an orbiting light
// beside two CPU-bound processes) these previews are what keeps the image moving.
#include "base/image.h"
#include "engine/render_context.h"
#include "engine/shade/pixel_factors.h"
#include "engine/trace/sample_cache.h"

namespace gloss {

class LightPreview {
 public:
  // A full-resolution light pass ran for ms: to its end (completed), or until it was cancelled
  // (then it takes at least that long).
  void light_pass(double ms, bool completed);
  // How much to shrink the preview (1: half the width and height, up to max_shift), or 0 when
  // the full-resolution pass is expected within budget_ms (or nothing is known yet). Before any
  // light pass was timed, trace_ms (a full-resolution 1-spp trace, which costs more than a
  // re-light) stands in for it.
  int shift(double budget_ms, int max_shift, double trace_ms) const;
  // The preview of ctx.scene at width x height into images: the total, and the four terms when
  // `terms`. false when cancelled.
  bool render(const RenderContext& ctx, int width, int height, TermImages& images, bool terms);

 private:
  double m_light_ms = -1;  // the last full-resolution light pass, -1: none yet
  SampleCache m_cache;
  PixelFactors m_factors;
};

}  // namespace gloss

#pragma once
// An edit's first image when the machine cannot make the full one quickly: while the
// full-resolution first pass of an edit's class (a re-shade, a re-summing of the cosines, a
// re-light) is expected to take longer than a budget (ProgressiveOptions::edit_preview_budget_ms),
// the progressive engine first shows the edit as a coarse image (a fresh 1-spp trace at 1/2, 1/4
// or 1/8 resolution, the finest expected within the budget) traced into a cache of its own, so
// the full-resolution caches stay as they are for the pass that follows. Under continuous edits
// on a loaded machine (an orbiting light or a slider drag beside two CPU-bound processes) these
// previews are what keeps the image moving.
#include "base/image.h"
#include "engine/change_class.h"
#include "engine/render_context.h"
#include "engine/shade/pixel_factors.h"
#include "engine/trace/sample_cache.h"

namespace gloss {

class EditPreview {
 public:
  // A full-resolution first pass of an edit of class `change` (shade, exponent or light) ran for
  // ms: to its end (completed), or until it was cancelled (then it takes at least that long).
  void first_pass(ChangeClass change, double ms, bool completed);
  // How much to shrink the preview of an edit of class `change` (1: half the width and height,
  // up to max_shift), or 0 when its full-resolution pass is expected within budget_ms (or nothing
  // is known yet). Before any light pass was timed, trace_ms (a full-resolution 1-spp trace,
  // which costs more than a re-light) stands in for it.
  int shift(ChangeClass change, double budget_ms, int max_shift, double trace_ms) const;
  // The preview of ctx.scene at width x height into images: the total, and the four terms when
  // `terms`. false when cancelled.
  bool render(const RenderContext& ctx, int width, int height, TermImages& images, bool terms);

 private:
  double m_pass_ms[3] = {-1, -1, -1};  // the last full-resolution first pass per class, -1: none
  SampleCache m_cache;
  PixelFactors m_factors;
};

}  // namespace gloss

// What one pass of the progressive engine computes (progressive_state.h): the image size (a
// restart, the next preview level), then the cheapest stage the edits since the last pass
// invalidated, adaptive refinement, or more samples.
#include <algorithm>

#include "engine/environment/environment_stage.h"
#include "engine/progressive_state.h"
#include "engine/trace/single_sample_pass.h"
#include "engine/trace/texture_lanes.h"

namespace gloss {

void ProgressiveRenderer::Impl::start_level(int new_level) {
  level = new_level;
  const RenderSettings& r = scene->render;
  const int shift = options.preview_levels - level;  // 3, 2, 1 -> 1/8, 1/4, 1/2
  const int w = std::max(1, r.width >> shift), h = std::max(1, r.height >> shift);
  const int target = level == options.preview_levels && !adaptive() ? r.spp : 1;
  reset_sample_cache(cache, *scene, w, h, target);  // keeps the memory of the last image
}

// One unit of work, then a publication; false when cancelled by a newer scene. A cancelled
// stage leaves `dirty` at the class that redoes it, so the caches never mix two scenes.
bool ProgressiveRenderer::Impl::step() {
  const Clock::time_point start = Clock::now();
  {
    std::lock_guard<std::mutex> lock(mutex);
    first_in_flight = pass == 0;
  }
  refined_traced = 0;
  // An edit whose full image is not expected within the budget shows a preview first.
  const bool edit_pass =
      level == options.preview_levels && dirty != ChangeClass::none && dirty != ChangeClass::full;
  if (edit_pass && pass == 0) {
    const int shift = edit_preview.shift(dirty, options.edit_preview_budget_ms,
                                         options.preview_levels, last_full_pass_ms);
    if (shift > 0) return preview_edit(shift, start);
  }
  const ChangeClass edit = dirty;
  std::atomic<long long> rays{0};
  ctx.rays = &rays;
  ChangeClass redo = ChangeClass::none;  // what a cancellation leaves to do
  bool ok = true;
  bool factors_done = false;  // the fused first pass builds the pixel factors too
  bool total_done = false;    // ... and, when only the total is shown, the frame's total image
  // The image size first (a restart or the next preview level), then the frame to fill.
  const bool restart = dirty == ChangeClass::full;
  const bool next_level = dirty == ChangeClass::none && level < options.preview_levels;
  SampleCache previous;  // next_level: the current resolution, kept until the next is complete
  const int previous_level = level;
  if (restart) {
    start_level(options.preview_levels > 0 ? 0 : options.preview_levels);
    adaptive_state.restart();
  } else if (next_level) {
    previous = std::move(cache);
    const bool skip = last_full_pass_ms >= 0 && last_full_pass_ms <= options.preview_budget_ms;
    // Its spare planes and refined buffers hold no data: the new image takes them now, its
    // planes in use once the new image is complete (reclaim_planes below).
    cache.spare = std::move(previous.spare);
    previous.spare.clear();
    cache.refined.plane = std::move(previous.refined.plane);
    start_level(skip ? options.preview_levels : level + 1);
  }
  const std::shared_ptr<RenderedFrame> frame =
      FramePool::make(frame_pool, cache.width, cache.height, worker_terms);
  // The first pass makes the total itself (and the sky, when the environment is the
  // background) unless a term view wants the terms.
  Image* const total = worker_terms ? nullptr : &frame->images.total;
  // The environment's estimates belong to the cache's samples and slots as they are: an edit
  // that rewrites the slots (environment, light) or the samples (full) starts them again, from
  // the fast path. Edits below keep them (a material edit only recombines).
  if (dirty >= ChangeClass::environment) environment.reset();
  const int environment_steps =
      dirty == ChangeClass::none && samples_done() ? next_environment_steps(ctx, environment) : 0;
  if (restart) {
    redo = ChangeClass::full;
    sky_current = false;
    ok = trace_single_sample(cache, ctx, factors, total);
    factors_done = total_done = true;
  } else if (dirty == ChangeClass::environment) {
    redo = ChangeClass::environment;  // its factors from the cached hits, no rays
    ok = recompute_environment_factors(cache, ctx);
  } else if (dirty == ChangeClass::texture) {
    redo = ChangeClass::texture;  // the maps at the cached hits, no rays
    ok = resample_textures(cache, ctx) &&
         (!ctx.plan.environment || recompute_environment_factors(cache, ctx));
  } else if (dirty == ChangeClass::light) {
    redo = ChangeClass::light;
    // One plane (one sample per pixel, or adaptive sampling's centres): light and pixel factors
    // in one pass. Refined samples are re-lit after it (refine()), once this image is shown.
    if (cache.samples() == 1) {
      ok = relight_single_sample(cache, ctx, factors, total);
      factors_done = total_done = true;
      if (total != nullptr && cache.refined.spp > 0) refined_sky_stale = true;
    } else {
      ok = recompute_light_factors(cache, ctx);
    }
  } else if (next_level) {
    // The next resolution is traced aside; the current one stays until it is complete.
    redo = ChangeClass::exponent;  // cancelled: the factors must be rebuilt from `previous`
    sky_current = false;
    ok = trace_single_sample(cache, ctx, factors, total);
    factors_done = total_done = true;
    if (ok) {
      reclaim_planes(cache, std::move(previous));
    } else {
      SampleCache traced = std::move(cache);
      cache = std::move(previous);
      level = previous_level;
      reclaim_planes(cache, std::move(traced));
    }
  } else if (environment_steps > 0) {
    redo = ChangeClass::environment;  // cancelled: back to the fast path, estimates anew
    ok = add_environment_steps(cache, ctx, environment, environment_steps);
  } else if (dirty == ChangeClass::none && adaptive()) {
    redo = ChangeClass::exponent;  // cancelled: the factors are rebuilt from the samples
    const std::vector<std::uint32_t> placed = cache.refined.pixels;
    // The same placement keeps the refined samples' hits (re-lit at most), and so the sky.
    const bool sky_kept = sky_current && !refined_sky_stale;
    sky_current = false;
    ok = refine(total, total_done);
    sky_current = sky_kept && ok && cache.refined.pixels == placed;
    // A new placement of the refined samples (re-chosen after an edit): the environment's
    // estimates start again, their sums being per refined entry and new entries holding the
    // fast path (remapping the kept entries' sums instead would keep their estimates). The centre
    // image, made with the estimates, then no longer holds the other pixels' totals: the frame's
    // total is made whole. Without an environment light the centre image is the centres' total
    // whatever the placement (after a restart too, where this whole-image pass took 1 to 1.5 ms
    // of the camera change's adaptive pass on the benchmark scene).
    if (cache.refined.pixels != placed) environment.reset();
    // The refined pixels' sky is not current (a new placement, a light edit's fused pass): it is
    // made again below (environment_sky), and so the total, whole. (An environment light implies
    // a sky, so a new placement under one always takes this path.)
    if (!sky_current && ctx.plan.sky) total_done = false;
    factors_done = true;
  } else if (dirty == ChangeClass::none) {
    // Double the samples each pass: 1, 2, 4, 8 ... up to the target.
    const int have = cache.samples();
    sky_current = false;
    ok = add_samples(cache, ctx, std::min(have, scene->render.spp - have));
  }
  if (ok && dirty != ChangeClass::shade && !factors_done) {
    redo = std::max(redo, ChangeClass::exponent);
    ok = adaptive_state.build_factors(cache, ctx, factors);
  }
  // The sky follows the camera, the samples and the environment's map and rotation, whatever
  // the edit's class (changes_sky): it is made again only when one of those changed, unless a
  // fused pass with the total made it already (emptied when the plan has none).
  const bool fused_total = total_done && total != nullptr;
  const bool sky_made = !sky_current && !fused_total;
  if (ok && sky_made) ok = environment_sky(cache, ctx, factors);
  if (ok && sky_made) refined_sky_stale = false;
  if (ok) sky_current = true;
  ctx.rays = nullptr;
  if (!ok) {
    dirty = std::max(dirty, redo);
    if (cache.samples() == 0) dirty = ChangeClass::full;
    if (edit_pass) edit_preview.first_pass(edit, ms_between(start, Clock::now()), false);
    return false;
  }
  dirty = ChangeClass::none;
  if (!total_done || total == nullptr) combine_terms(factors, ctx, frame->images, worker_terms);
  const double pass_ms = ms_between(start, Clock::now());
  if ((restart || next_level) && level == options.preview_levels) last_full_pass_ms = pass_ms;
  if (edit_pass) edit_preview.first_pass(edit, pass_ms, true);
  frame->info.sky_sampled = ctx.plan.sky && (sky_made || fused_total);
  publish(frame, pass_ms, rays.load(), converged_state());
  return true;
}

bool ProgressiveRenderer::Impl::preview_edit(int shift, Clock::time_point start) {
  const int w = std::max(1, scene->render.width >> shift);
  const int h = std::max(1, scene->render.height >> shift);
  const std::shared_ptr<RenderedFrame> frame = FramePool::make(frame_pool, w, h, worker_terms);
  std::atomic<long long> rays{0};
  ctx.rays = &rays;
  const bool ok = edit_preview.render(ctx, w, h, frame->images, worker_terms);
  ctx.rays = nullptr;
  if (!ok) return false;  // `dirty` stays as it was
  published_centres = false;
  frame->info.sky_sampled = ctx.plan.sky;  // a fresh trace of its own
  publish_frame(frame, w, h, 1, ms_between(start, Clock::now()), rays.load(), false);
  return true;
}

bool ProgressiveRenderer::Impl::refine(Image* total, bool& total_done) {
  std::shared_ptr<const RenderedFrame> shown;
  if (published_centres) {
    std::lock_guard<std::mutex> lock(publish_mutex);
    shown = published;
  }
  const Image* centres = shown ? &shown->images.total : nullptr;
  const bool ok = adaptive_state.refine(cache, ctx, factors, centres);
  refined_traced = adaptive_state.traced();
  if (ok && total != nullptr && centres != nullptr) {
    combine_over_centres(factors, ctx, *centres, *total);
    total_done = true;
  }
  return ok;
}

}  // namespace gloss

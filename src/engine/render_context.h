#pragma once
// Everything a render stage reads: the scene, its Embree twin, the plan and the camera frame for
// the image being computed, plus the cancellation flag and ray counter of the caller.
#include <atomic>

#include "engine/environment/environment_context.h"
#include "engine/render_plan.h"
#include "engine/trace/embree_scene.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace gloss {

struct RenderContext {
  const Scene* scene = nullptr;
  const EmbreeScene* embree = nullptr;
  RenderPlan plan;
  EnvironmentContext environment;             // the environment's tables (plan.environment)
  const std::atomic<bool>* cancel = nullptr;  // stages return false soon after it turns true
  std::atomic<long long>* rays = nullptr;     // primary + shadow rays traced, when not null

  bool cancelled() const { return cancel != nullptr && cancel->load(std::memory_order_relaxed); }
};

// Points ctx at scene and its Embree twin, with the scene's plan (full_plan: the oracle's,
// make_render_plan) and the environment's tables for it.
inline void bind_scene(RenderContext& ctx, const Scene& scene, const EmbreeScene& embree,
                       bool full_plan = false) {
  ctx.scene = &scene;
  ctx.embree = &embree;
  ctx.plan = make_render_plan(scene, full_plan);
  ctx.environment = make_environment_context(scene, ctx.plan.environment);
}

// A context for scene and its Embree twin with the scene's own plan, no cancellation or count.
inline RenderContext make_render_context(const Scene& scene, const EmbreeScene& embree) {
  RenderContext ctx;
  bind_scene(ctx, scene, embree);
  return ctx;
}

}  // namespace gloss

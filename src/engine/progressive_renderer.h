#pragma once
// The interactive engine: renders a scene progressively on oneTBB workers, coarse to fine, and
// publishes each finished pass whole. set_scene() never blocks on rendering; it classifies the
// edit (change_class.h) and restarts at the cheapest stage the edit invalidates.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "base/image.h"
#include "engine/change_class.h"
#include "scene/scene.h"

namespace gloss {

struct FrameInfo {
  std::uint64_t generation = 0;    // counts set_scene() calls that changed something
  int pass = 0;                    // passes published for this generation so far, from 0
  int width = 0, height = 0;       // size of this pass's images (coarse passes are smaller)
  int spp = 0;                     // samples per pixel in these images
  int target_spp = 0;              // scene.render.spp
  double pass_ms = 0;              // compute time of this pass
  double since_change_ms = 0;      // from the set_scene() of this generation to publication
  long long rays = 0;              // primary + shadow rays traced for this pass
  std::size_t refined_traced = 0;  // adaptive: pixels whose refined samples it traced anew
  bool sky_sampled = false;        // it sampled the sky anew (the map where rays missed)
  bool converged = false;          // nothing more will be computed for this scene
  // An environment light's exact path (docs/engine.md, "The environment"): the directions every
  // sample has taken so far, against render.env_samples. 0 of N: the environment is still the
  // fast path's (no shadows, no horizon). env_target 0: no exact path to take.
  int env_steps = 0, env_target = 0;
  ChangeClass cause = ChangeClass::full;  // what the edit that led here invalidated
};

struct RenderedFrame {
  FrameInfo info;
  TermImages images;  // total always; the four terms when ProgressiveOptions::terms is set
  // Adaptive sampling: the pixels given spp stratified samples (y * width + x, ascending); the
  // others hold their centre sample. render() with this placement gives the same images.
  std::vector<std::uint32_t> refined;
};

struct ProgressiveOptions {
  bool terms = true;       // publish the four term images as well as the total
  int preview_levels = 3;  // coarse passes before full resolution: 1/8, 1/4, 1/2
  // When the last full-resolution 1-spp pass took at most this long, the image goes from the
  // coarsest preview straight to full resolution: the finer previews would only delay it.
  // 0: always every preview. 50 ms, the pace max_publish_gap_ms keeps under edits: a full image
  // that soon after the 1/8 preview needs nothing between them, and the 1/4 and 1/2 previews
  // cost a third of a full pass (at 25 ms a loaded 2-core machine, whose full pass takes 25 to
  // 45 ms on the benchmark scene, paid them on every camera change).
  double preview_budget_ms = 50.0;
  // An edit cancels the pass in flight, unless that pass is the first image of its generation
  // and nothing was published for this long: then the pass completes first. Under edits that
  // come faster than a pass (a drag, an animation on a loaded machine) images keep coming, each
  // at most one pass behind the newest edit. 0: first images are never cancelled.
  double max_publish_gap_ms = 50.0;
  // An edit (shade, exponent, light) whose full-resolution first pass is expected to take longer
  // than this (the last of its class did, or ran that long before it was cancelled) first shows
  // a coarse preview traced afresh at the finest of 1/2, 1/4, 1/8 of the size expected within it
  // (edit_preview.h), then the full image. 0: never.
  double edit_preview_budget_ms = 25.0;
};

// The name of each engine's own thread (the one that takes edits in and publishes frames), as
// the kernel shows it (/proc/self/task/TID/comm).
inline constexpr char kEngineThreadName[] = "gloss-engine";

class ProgressiveRenderer {
 public:
  explicit ProgressiveRenderer(ProgressiveOptions options = {});
  ~ProgressiveRenderer();  // cancels work in flight and joins
  ProgressiveRenderer(const ProgressiveRenderer&) = delete;
  ProgressiveRenderer& operator=(const ProgressiveRenderer&) = delete;

  // Hands the engine a new version of the document. Cheap: copies the scene and wakes the worker.
  // Returns the generation its frames will carry (the current one when nothing changed).
  std::uint64_t set_scene(const Scene& scene);
  // Cancels the pass in flight and computes nothing more until the next set_scene() (even one
  // with the same scene), keeping the scene, the BVH and the caches: the editor pauses the ray
  // tracer while the raster path draws a drag, so the two do not share the cores.
  void pause();
  // Whether the four term images are published (the editor turns this on for the term views);
  // the same value again does nothing.
  void set_terms(bool terms);

  // The newest published frame, or null before the first. Never blocks on rendering; the frame
  // is immutable and stays valid while held.
  std::shared_ptr<const RenderedFrame> latest() const;

  // Blocks until the current generation has converged or timeout_ms passed; true if converged.
  bool wait_converged(double timeout_ms) const;

  // Called on the worker thread after each publication (the editor wakes its event loop).
  void set_on_publish(std::function<void()> callback);

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace gloss

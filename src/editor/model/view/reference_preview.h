#pragma once
// The A/B view's physical-reference side (AbSource::reference): the document rendered by the
// reference path with ReferenceOptions::physical (docs/spec/physical-reference.md), in double at
// one sample per pixel, on a worker thread so the UI never waits. Its interface is the part of
// the progressive renderer's the viewport uses (engine/progressive_renderer.h), so the viewport
// shows its frames the same way. One pass per document: a new one cancels the pass in flight.
#include <cstdint>
#include <functional>
#include <memory>

#include "engine/progressive_renderer.h"
#include "scene/scene.h"

namespace gloss {

class ReferencePreview {
 public:
  ReferencePreview();
  ~ReferencePreview();  // cancels the pass in flight and joins
  ReferencePreview(const ReferencePreview&) = delete;
  ReferencePreview& operator=(const ReferencePreview&) = delete;

  // Hands over a new version of the document (rendered at scene.render's size, 1 spp). Cheap:
  // copies the scene and wakes the worker. Returns the generation its frame will carry (the
  // current one when nothing changed).
  std::uint64_t set_scene(const Scene& scene);
  // The newest finished frame (all four terms and the total), or null before the first.
  std::shared_ptr<const RenderedFrame> latest() const;
  // Blocks until the current generation's frame is published or timeout_ms passed.
  bool wait_converged(double timeout_ms) const;
  // Called on the worker after each publication (the editor wakes its event loop).
  void set_on_publish(std::function<void()> callback);

 private:
  struct Impl;
  std::unique_ptr<Impl> m;
};

}  // namespace gloss

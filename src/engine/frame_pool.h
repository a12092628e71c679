#pragma once
// Published frames whose images are recycled: a full-resolution total is 11 MB at 1280x720, and
// allocating it afresh for every pass cost the progressive engine its page faults and zeroing
// (about 3 ms a pass on the benchmark scene, docs/engine.md). A frame made here returns its
// pixel buffers to the pool when its last holder lets go, whichever thread that is; the pool's
// mutex orders that release before the buffers' reuse.
#include <memory>
#include <mutex>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/progressive_renderer.h"

namespace gloss {

class FramePool {
 public:
  // A new frame whose images (the total, and the four terms when `terms`) are width x height
  // with unspecified pixels (every pass overwrites all of them). The pool outlives the frames
  // it made.
  static std::shared_ptr<RenderedFrame> make(const std::shared_ptr<FramePool>& pool, int width,
                                             int height, bool terms);

 private:
  void give_back(RenderedFrame& frame);
  Image take(int width, int height);

  std::mutex m_mutex;
  std::vector<std::vector<glm::vec3>> m_buffers;  // at most kKept, the largest kept
};

}  // namespace gloss

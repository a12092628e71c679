#pragma once
// What the progressive engine's tests share: every frame an edit publishes, and the largest
// channel difference of two images.
#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <vector>

#include <gtest/gtest.h>

#include "engine/progressive_renderer.h"

namespace gloss::test {

// Every frame the engine publishes for `scene` (handed in now), up to its converged one.
inline std::vector<std::shared_ptr<const RenderedFrame>> frames_of(ProgressiveRenderer& engine,
                                                                   const Scene& scene,
                                                                   double timeout_ms = 60000) {
  std::vector<std::shared_ptr<const RenderedFrame>> frames;
  std::mutex mutex;
  engine.set_on_publish([&] {
    std::lock_guard<std::mutex> lock(mutex);
    frames.push_back(engine.latest());
  });
  engine.set_scene(scene);
  EXPECT_TRUE(engine.wait_converged(timeout_ms));
  engine.set_on_publish(nullptr);
  std::lock_guard<std::mutex> lock(mutex);
  return frames;
}

// The largest difference in any channel of any pixel; infinite when the sizes differ.
inline double max_abs_diff(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) return INFINITY;
  double worst = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(double(a.pixels[i][c]) - double(b.pixels[i][c])));
  return worst;
}

}  // namespace gloss::test

#include "engine/frame_pool.h"

#include <algorithm>

#include "engine/best_fit.h"

namespace gloss {

namespace {
// Buffers kept: the frame on screen, the one being rendered, and the terms of a term view.
constexpr std::size_t kKept = 12;
}  // namespace

std::shared_ptr<RenderedFrame> FramePool::make(const std::shared_ptr<FramePool>& pool, int width,
                                               int height, bool terms) {
  auto* frame = new RenderedFrame;
  frame->images.total = pool->take(width, height);
  if (terms) {
    for (Image* image : {&frame->images.emissive, &frame->images.ambient, &frame->images.diffuse,
                         &frame->images.specular}) {
      *image = pool->take(width, height);
    }
  }
  return std::shared_ptr<RenderedFrame>(frame, [pool](RenderedFrame* f) {
    pool->give_back(*f);
    delete f;
  });
}

Image FramePool::take(int width, int height) {
  const std::size_t size = static_cast<std::size_t>(width) * height;
  Image image;
  image.width = width;
  image.height = height;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    // By size, not capacity: growing a vector within its capacity still zero-fills the new
    // elements. And a buffer over twice the size stays for a larger image: with only the frame
    // on screen and the one being rendered alive, the coarse previews after a camera change took
    // the full-size buffers and shrank them, and the full-size passes after them zero-filled
    // 11 MB each on the engine's thread (some 2 % of the adaptive benchmark's time).
    const auto best = best_fit(m_buffers.begin(), m_buffers.end(), size,
                               [](const std::vector<glm::vec3>& b) { return b.size(); });
    if (best != m_buffers.end() && !(best->size() > 2 * size)) {
      image.pixels = std::move(*best);
      m_buffers.erase(best);
    }
  }
  image.pixels.resize(size);  // no zeroing when it fits: the old values are overwritten
  return image;
}

void FramePool::give_back(RenderedFrame& frame) {
  std::lock_guard<std::mutex> lock(m_mutex);
  for (Image* image : {&frame.images.total, &frame.images.emissive, &frame.images.ambient,
                       &frame.images.diffuse, &frame.images.specular}) {
    if (image->pixels.empty()) continue;
    m_buffers.push_back(std::move(image->pixels));
  }
  if (m_buffers.size() > kKept) {  // drop the smallest (by size, as take() chooses)
    std::sort(m_buffers.begin(), m_buffers.end(),
              [](const auto& a, const auto& b) { return a.size() > b.size(); });
    m_buffers.resize(kKept);
  }
}

}  // namespace gloss

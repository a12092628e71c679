#include "scene/memory_estimate.h"

namespace gloss {

std::uint64_t teapot_triangles(int level) {
  const auto l = static_cast<std::uint64_t>(level);
  return 32 * 2 * l * l;
}

std::uint64_t geometry_bytes(std::uint64_t triangles) {
  return triangles * kBytesPerTriangle;
}

std::uint64_t render_bytes(const RenderSettings& render, std::size_t lights) {
  const std::uint64_t pixels =
      static_cast<std::uint64_t>(render.width) * static_cast<std::uint64_t>(render.height);
  const std::uint64_t samples = pixels * static_cast<std::uint64_t>(render.spp);
  // At most 64 Mi pixels * 4096 spp = 2^38 samples: no overflow for any light count in memory.
  return pixels * kBytesPerPixel + samples * (kBytesPerSample + kBytesPerSampleLight * lights);
}

}  // namespace gloss

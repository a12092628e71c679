#include "scene/memory/memory_estimate.h"

#include <algorithm>

namespace gloss {

std::uint64_t teapot_triangles(int level) {
  const auto l = static_cast<std::uint64_t>(level);
  return 32 * 2 * l * l;
}

std::uint64_t geometry_bytes(std::uint64_t triangles) {
  return triangles * kBytesPerTriangle;
}

std::uint64_t sample_row_bytes(int width, int spp, std::size_t lights) {
  return static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(spp) *
         (20 + 16 * std::max<std::uint64_t>(1, lights));
}

int sample_band_rows(int width, int height, int spp, std::size_t lights) {
  const std::uint64_t fit =
      std::max<std::uint64_t>(1, kSampleBandBytes / sample_row_bytes(width, spp, lights));
  return static_cast<int>(
      std::min<std::uint64_t>(static_cast<std::uint64_t>(height), std::max<std::uint64_t>(4, fit)));
}

std::uint64_t render_bytes(const RenderSettings& render, std::size_t lights, SampleMemory samples) {
  const std::uint64_t pixels =
      static_cast<std::uint64_t>(render.width) * static_cast<std::uint64_t>(render.height);
  const int rows = samples == SampleMemory::banded
                       ? sample_band_rows(render.width, render.height, render.spp, lights)
                       : render.height;
  // At most 64 Mi pixels * 4096 spp * (20 + 16 lights) bytes: 2^38 * 36 for one light, far from
  // overflowing 64 bits for any light count that fits in memory.
  return pixels * (kBytesPerPixel + kBytesPerPixelLight * lights) +
         static_cast<std::uint64_t>(rows) * sample_row_bytes(render.width, render.spp, lights);
}

std::uint64_t environment_bytes(const Environment& environment) {
  if (!environment.present()) return 0;
  const Image& map = environment.map->radiance;
  return static_cast<std::uint64_t>(map.width) * map.height * kEnvironmentBytesPerTexel;
}

}  // namespace gloss

namespace gloss {

std::uint64_t texture_bytes(const Scene& scene) {
  std::vector<const Texture*> seen;
  std::uint64_t total = 0;
  for (const Material& material : scene.materials) {
    for (int slot = 0; slot < kMapSlots; ++slot) {
      const Texture* t = material.map(static_cast<MapSlot>(slot)).texture.get();
      if (t == nullptr || std::find(seen.begin(), seen.end(), t) != seen.end()) continue;
      seen.push_back(t);
      total += t->bytes();
    }
  }
  return total;
}

}  // namespace gloss

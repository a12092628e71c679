#include "editor/ui/panels/map_thumbnails.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gloss {

namespace {

unsigned char display_byte(float linear, bool colour) {
  float x = std::clamp(std::isfinite(linear) ? linear : 0.0f, 0.0f, 1.0f);
  if (colour) x = x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
  return static_cast<unsigned char>(std::lround(x * 255.0f));
}

}  // namespace

GLuint MapThumbnails::get(const std::shared_ptr<const Texture>& texture, bool colour) {
  if (!texture || texture->levels.empty()) return 0;
  const auto key = std::make_pair(texture.get(), colour);
  auto found = m_entries.find(key);
  if (found == m_entries.end()) {
    // The first level that fits, so the preview is a filtered image, not every n-th texel.
    std::size_t l = 0;
    while (l + 1 < texture->levels.size() &&
           std::max(texture->levels[l].width, texture->levels[l].height) > kSize) {
      ++l;
    }
    const MipLevel& level = texture->levels[l];
    std::vector<unsigned char> rgb(static_cast<std::size_t>(level.width) * level.height * 3);
    const auto channels = static_cast<std::size_t>(texture->channels);
    for (std::size_t p = 0; p < rgb.size() / 3; ++p) {
      for (std::size_t c = 0; c < 3; ++c) {
        rgb[3 * p + c] = display_byte(level.texels[p * channels + (channels == 1 ? 0 : c)], colour);
      }
    }
    Entry entry;
    entry.texture = texture;
    entry.preview.upload_rgb8(level.width, level.height, rgb.data());
    found = m_entries.emplace(key, std::move(entry)).first;
  }
  found->second.used = true;
  return found->second.preview.id();
}

void MapThumbnails::prune() {
  for (auto it = m_entries.begin(); it != m_entries.end();) {
    if (!it->second.used) {
      it = m_entries.erase(it);
    } else {
      it->second.used = false;
      ++it;
    }
  }
}

}  // namespace gloss

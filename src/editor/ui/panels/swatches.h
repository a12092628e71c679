#pragma once
// The preset swatches: one small sphere per preset, rendered once at start-up by the core
// renderer on a worker thread, then uploaded as textures on the UI thread.
#include <future>
#include <vector>

#include "editor/gl/gl_texture.h"

namespace gloss {

struct Material;

// One swatch, kSize x kSize 8-bit RGB (rows top first): a unit sphere of material lit from the
// upper right on a dark grey background, by the core renderer (the calling thread and oneTBB's).
std::vector<unsigned char> render_swatch(const Material& material);

class Swatches {
 public:
  static constexpr int kSize = 48;  // pixels per side

  // Starts rendering the preset table's spheres; returns immediately.
  void start();
  // Uploads the swatches once the worker has finished (call on the UI thread each frame).
  void poll();
  bool ready() const { return !m_textures.empty(); }
  // The swatch of preset i (preset_table() order), or 0 while rendering or on failure.
  GLuint texture(std::size_t preset) const;
  // Why the swatches failed, or empty.
  const std::string& error() const { return m_error; }
  // Bytes of the swatch textures (RGB8).
  std::size_t texture_bytes() const { return m_textures.size() * kSize * kSize * 3; }

 private:
  std::future<std::vector<std::vector<unsigned char>>> m_job;  // RGB8, kSize^2 * 3 each
  std::vector<GlTexture> m_textures;
  std::string m_error;
};

}  // namespace gloss

#pragma once
// Small previews of a material's maps for the Material panel: per texture, the first pyramid
// level at most kSize texels on a side, shown as 8-bit colour (colour maps sRGB-encoded for the
// display, data maps such as normals as stored). Uploaded once per texture on the UI thread;
// the textures of maps no longer drawn are dropped by prune().
#include <map>
#include <memory>

#include "editor/gl/gl_texture.h"
#include "texture/texture.h"

namespace gloss {

class MapThumbnails {
 public:
  static constexpr int kSize = 64;

  // The preview of texture (0 for null); colour: decode for display with the sRGB curve.
  GLuint get(const std::shared_ptr<const Texture>& texture, bool colour);
  // Drops the previews not asked for since the last prune().
  void prune();

 private:
  struct Entry {
    std::shared_ptr<const Texture> texture;  // keeps the key's address from being reused
    GlTexture preview;
    bool used = true;
  };
  std::map<std::pair<const Texture*, bool>, Entry> m_entries;
};

}  // namespace gloss

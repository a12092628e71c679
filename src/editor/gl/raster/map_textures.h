#pragma once
// The raster path's copies of the scene's maps (texture/texture.h): one GL float texture per
// Texture, with every mip level the pyramid has as that level (RGBA32F, or R32F for one
// channel), read by shaders/texture_lookup.glsl with texelFetch. A Texture is immutable and
// shared, so its copy is keyed by it and uploaded once; copies no material uses any more are
// freed at the next sync(), as raster_geometry.h does for meshes.
#include <cstddef>
#include <map>
#include <memory>

#include <glad/gl.h>

#include "scene/scene.h"

namespace gloss {

class MapTextures {
 public:
  MapTextures();  // needs a current GL context
  ~MapTextures();
  MapTextures(const MapTextures&) = delete;
  MapTextures& operator=(const MapTextures&) = delete;

  // Uploads the maps of scene's materials not uploaded yet and frees the others; returns the
  // number uploaded.
  int sync(const Scene& scene);
  // The GL texture of a texture of the scene last synced (an empty 1 x 1 texture for null).
  GLuint texture(const Texture* texture) const;
  // Bytes of texels held on the GL side (the editor's `memory` line).
  std::size_t bytes() const;

 private:
  struct Entry {
    std::shared_ptr<const Texture> texture;  // keeps the key's address from being reused
    GLuint name = 0;
  };
  std::map<const Texture*, Entry> m_textures;
  GLuint m_empty = 0;
};

// Binds material's maps for the program in use to texture units first_unit ... first_unit + 7
// and sets the maps' uniforms of shaders/raster_common.glsl (GLOSS_MAPS), with the scene's map
// filter and the camera's cone spread (texture/footprint.h).
void set_map_uniforms(GLuint program, const MapTextures& maps, const Material& material,
                      MapFilter filter, float cone_spread, int first_unit);

}  // namespace gloss

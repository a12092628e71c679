#pragma once
// The raster path's hard shadows: per point light a cube of six size x size float maps, each
// texel the distance from the light to the nearest surface in its direction (layer 6 i + k: face
// k of light i, a GL_TEXTURE_2D_ARRAY read by raster_common.glsl's gloss_visibility). Drawn
// with MIN blending rather than a depth test, so the stored value is the nearest distance any
// fragment found, as exact as the fragment's own arithmetic. Redrawn only when the lights, the
// geometry or the size changed.
//
// Why not GL cube map textures: one samplerCube per light would need an array of samplers
// indexed by the light loop's counter, which GLSL 3.30 allows only with constant indices, and
// cube map arrays are GL 4.0. Six layers per light in one array texture, with the face chosen
// by the same major-axis rule GL uses, is a cube map that a loop can index.
#include <cstddef>
#include <functional>
#include <vector>

#include <glad/gl.h>

#include "editor/gl/raster_view.h"
#include "scene/scene.h"

namespace gloss {

// The most texel storage the maps may take, bytes: 32 lights at 4096 texels would ask for
// 12.9 GB; a request past this is refused with a message instead of failing in the driver.
inline constexpr std::size_t kMaxShadowMapBytes = std::size_t(1) << 30;

class ShadowMaps {
 public:
  ShadowMaps() = default;  // GL objects are made on the first update()
  ~ShadowMaps();
  ShadowMaps(const ShadowMaps&) = delete;
  ShadowMaps& operator=(const ShadowMaps&) = delete;

  // Makes the maps hold scene's lights and geometry at size texels per face side; draw(view)
  // must draw every object's distance from view.origin with the shadow programs into the
  // framebuffer and viewport set up here. Returns true when it drew, false when the maps it
  // already held were still right.
  bool update(const Scene& scene, int size, const std::function<void(const RasterView&)>& draw);

  GLuint texture() const { return m_texture; }
  int size() const { return m_size; }
  std::size_t bytes() const;  // texel storage held, for the `memory` line

 private:
  // What the maps depend on: the light positions and every object's geometry (the sphere, or
  // the identity of its immutable Mesh), and the size.
  std::vector<float> m_key_numbers;
  std::vector<const void*> m_key_meshes;
  int m_size = 0, m_layers = 0;
  GLuint m_texture = 0, m_framebuffer = 0;
};

}  // namespace gloss

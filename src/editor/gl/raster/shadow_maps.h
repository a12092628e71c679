#pragma once
// The raster path's hard shadows, size x size float maps in one GL_TEXTURE_2D_ARRAY read by
// raster_common.glsl's gloss_visibility: per point light (and per spot wider than 60 degrees) a
// cube of six, each texel the distance from the light to the nearest surface in its direction;
// per narrower spot one perspective map along its axis; per directional light one orthographic
// map across the scene (fitted to every object's box, raster_view.h directional_view), each
// texel the depth along the light's way. Drawn with MIN blending rather than a depth test, so
// the stored value is the nearest any fragment found, as exact as the fragment's own
// arithmetic. Redrawn only when the lights, the geometry or the size changed.
//
// Why not GL cube map textures: one samplerCube per light would need an array of samplers
// indexed by the light loop's counter, which GLSL 3.30 allows only with constant indices, and
// cube map arrays are GL 4.0. Six layers per light in one array texture, with the face chosen
// by the same major-axis rule GL uses, is a cube map that a loop can index.
#include <cstddef>
#include <functional>
#include <vector>

#include <glad/gl.h>

#include "editor/gl/raster/raster_view.h"
#include "scene/scene.h"

namespace gloss {

// The most texel storage the maps may take, bytes: 32 lights at 4096 texels would ask for
// 12.9 GB; a request past this is refused with a message instead of failing in the driver.
inline constexpr std::size_t kMaxShadowMapBytes = std::size_t(1) << 30;

// The widest spot cutoff a single perspective map covers, degrees: beyond it the frustum's
// corners (tan 60 = 1.73 across) spread a texel over too much of the cone; wider spots, up to
// 90, take the six cube faces a point light takes.
inline constexpr float kMaxSpotMapCutoff = 60.0f;

// Where one light's maps are (raster_common.glsl's GLOSS_SHADOW_* kinds).
struct LightShadow {
  enum Kind { cube = 0, perspective = 1, orthographic = 2 };
  Kind kind = cube;
  int first_layer = 0;  // of the array texture; a cube takes 6 from here
  RasterView view;      // perspective and orthographic: the map's view
};

class ShadowMaps {
 public:
  ShadowMaps() = default;  // GL objects are made on the first update()
  ~ShadowMaps();
  ShadowMaps(const ShadowMaps&) = delete;
  ShadowMaps& operator=(const ShadowMaps&) = delete;

  // Makes the maps hold scene's lights and geometry (boxes: drawn_boxes(scene)) at size texels
  // per side; draw(view) must draw every object's gloss_view_distance with the shadow programs
  // into the framebuffer and viewport set up here. Returns true when it drew, false when the
  // maps it already held were still right.
  bool update(const Scene& scene, const std::vector<DrawnBox>& boxes, int size,
              const std::function<void(const RasterView&)>& draw);

  // Per scene light, where its maps are (valid after update()).
  const std::vector<LightShadow>& lights() const { return m_lights; }

  GLuint texture() const { return m_texture; }
  int size() const { return m_size; }
  std::size_t bytes() const;  // texel storage held, for the `memory` line

 private:
  // What the maps depend on: the light positions and every object's geometry (the sphere, or
  // the identity of its immutable Mesh), and the size.
  std::vector<float> m_key_numbers;
  std::vector<LightShadow> m_lights;
  std::vector<const void*> m_key_meshes;
  int m_size = 0, m_layers = 0;
  GLuint m_texture = 0, m_framebuffer = 0;
};

}  // namespace gloss

#pragma once
// A material's map as the export formats carry it (docs/export.md, "Maps"): the image file a
// map names, referred to from the exported file, and gloss's map coordinates ((u, v) * scale,
// turned counter-clockwise by rotation, plus offset; v up) as glTF's KHR_texture_transform and
// as three.js's texture fields.
#include <string>

#include <glm/vec2.hpp>

#include "scene/scene.h"

namespace gloss {

// The image a map names, for a file written to out_path.
struct MapImage {
  std::string file;  // the image on disk (the scene's name resolved against its folder)
  std::string uri;   // file relative to out_path's folder, '/'-separated
  std::string mime;  // "image/png" or "image/jpeg"
  // Why it cannot be carried ("" when it can): a model's own map, or an image that is not PNG
  // or JPEG (what glTF allows and every browser decodes).
  std::string problem;
};
MapImage map_image(const Scene& scene, const TextureMap& map, const std::string& out_path);

// KHR_texture_transform: uv' = T(offset) R(rotation) S(scale) uv on glTF's (u, v), v down, with
// R(r) = [[cos r, sin r], [-sin r, cos r]]. The exported meshes carry (u, 1 - v), so gloss's map
// is scale s, rotation r (radians) and offset (o.x - s.y sin r, 1 - o.y - s.y cos r); io's glTF
// map reader (io/model/gltf_maps.cpp) undoes exactly this.
struct GltfTextureTransform {
  glm::dvec2 offset{0.0}, scale{1.0};
  double rotation = 0.0;  // radians
};
GltfTextureTransform gltf_texture_transform(const TextureMap& map);

// three.js's Texture (flipY true, its geometries' v up as gloss's): uv' = S(repeat)
// R(-rotation) uv + offset about center (0, 0) (Matrix3.setUvTransform). gloss rotates after
// scaling, three.js before, so the two agree when the scale is the same on both axes or the
// rotation is a multiple of 180 degrees; otherwise `exact` is false (three.js gets gloss's
// scale, rotation and offset, the nearest it can take).
struct ThreejsTextureTransform {
  glm::dvec2 repeat{1.0}, offset{0.0};
  double rotation = 0.0;  // radians, as three.js turns it
  bool exact = true;
};
ThreejsTextureTransform threejs_texture_transform(const TextureMap& map);

}  // namespace gloss

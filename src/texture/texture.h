#pragma once
// A texture map as every renderer path reads it (docs/spec/shading.md, "Textures"): a mip pyramid
// of linear float texels, built once when the map is read (mip_pyramid.h) and shared, immutable,
// by every copy of the scene that uses it (undo, the engine's, the editor's), as meshes are.
// Texel (i, j) of a level, j counted from the top row, has its centre at u = (i + 0.5) / W,
// v = 1 - (j + 0.5) / H: v points up the image.
#include <cstdint>
#include <string>
#include <vector>

namespace gloss {

// What a lookup does outside [0, 1], per axis: the texel index wraps around, stops at the edge
// texel, or runs back and forth (GL's REPEAT, CLAMP_TO_EDGE and MIRRORED_REPEAT).
enum class Wrap : std::uint8_t { repeat, clamp, mirror };

// "repeat" / "clamp" / "mirror".
const char* to_string(Wrap wrap);

struct MipLevel {
  int width = 0, height = 0;
  std::vector<float> texels;  // width * height * Texture::channels, row 0 at the top
};

struct Texture {
  // 1: one value per texel (grey, or a data map's first channel), read as (g, g, g, 1);
  // 4: red, green, blue, alpha (alpha 1 where the file had none).
  int channels = 4;
  bool has_alpha = false;        // the file had an alpha channel (an opacity map reads it)
  std::vector<MipLevel> levels;  // level 0 is the image; each next one half as large (floor,
                                 // at least 1), down to 1 x 1
  // Where it came from, for the panels and the inspector.
  std::string source;         // the file as opened; for a map made from a model, what it was
  std::string format;         // "PNG", "JPEG", "OpenEXR", "Radiance HDR", "made by gloss"
  int bits = 0;               // per sample as stored
  bool srgb_decoded = false;  // the samples went through the sRGB curve before filtering

  int width() const { return levels.empty() ? 0 : levels[0].width; }
  int height() const { return levels.empty() ? 0 : levels[0].height; }
  int level_count() const { return static_cast<int>(levels.size()); }
  std::uint64_t bytes() const;
};

}  // namespace gloss

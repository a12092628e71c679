#pragma once
// Which renderer the viewport uses and the raster (GLSL) path's knobs (issue 12). Preferences of
// the window like the rest of ViewSettings: not part of the document, not undone. The raster
// path itself lives in editor/gl (raster_renderer.h); this header is GL-free so that scripts,
// panels and tests of the model can name its settings.
#include <string>

namespace gloss {

// cpu: the ray tracer (exact, progressive). gl: the raster path, one sample per pixel.
// automatic: the raster path while the camera or a light is being dragged, the ray tracer when
// still (the viewport decides, viewport.h).
enum class RendererChoice { cpu, gl, automatic };
const char* to_string(RendererChoice choice);  // "cpu", "gl", "auto"
bool parse_renderer_choice(const std::string& name, RendererChoice& choice);

// Where the raster path evaluates the contract on meshes: per pixel (Phong shading: the
// normal and position interpolated, the contract at each pixel centre) or per vertex (Gouraud:
// the contract at each vertex, its terms interpolated). Spheres are ray-cast impostors and are
// always shaded per pixel.
enum class ShadingFrequency { pixel, vertex };
const char* to_string(ShadingFrequency frequency);  // "pixel", "vertex"
bool parse_shading_frequency(const std::string& name, ShadingFrequency& frequency);

// Range of RasterSettings::shadow_map_size, texels per cube face side.
inline constexpr int kMinShadowMapSize = 16;
inline constexpr int kMaxShadowMapSize = 4096;

struct RasterSettings {
  ShadingFrequency shading = ShadingFrequency::pixel;
  // Hard shadows (when the document's render.shadows is on) come from one cube shadow map per
  // point light: the distance from the light to the nearest surface per texel.
  int shadow_map_size = 1024;  // texels per cube face side, kMinShadowMapSize..kMaxShadowMapSize
  // A point is lit when its distance to the light is at most the stored distance plus this
  // many texels' worth of depth (scaled by the surface's slope to the light): too small gives
  // shadow acne, too large lets light leak under contact shadows. >= 0.
  float shadow_bias = 1.5f;
};

bool operator==(const RasterSettings& a, const RasterSettings& b);
inline bool operator!=(const RasterSettings& a, const RasterSettings& b) {
  return !(a == b);
}

}  // namespace gloss

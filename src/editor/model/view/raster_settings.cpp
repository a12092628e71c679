#include "editor/model/view/raster_settings.h"

namespace gloss {

const char* to_string(RendererChoice choice) {
  switch (choice) {
    case RendererChoice::cpu:
      return "cpu";
    case RendererChoice::gl:
      return "gl";
    case RendererChoice::automatic:
      return "auto";
  }
  return "?";
}

bool parse_renderer_choice(const std::string& name, RendererChoice& choice) {
  for (RendererChoice c : {RendererChoice::cpu, RendererChoice::gl, RendererChoice::automatic}) {
    if (name == to_string(c)) {
      choice = c;
      return true;
    }
  }
  return false;
}

const char* to_string(ShadingFrequency frequency) {
  switch (frequency) {
    case ShadingFrequency::pixel:
      return "pixel";
    case ShadingFrequency::vertex:
      return "vertex";
  }
  return "?";
}

bool parse_shading_frequency(const std::string& name, ShadingFrequency& frequency) {
  for (ShadingFrequency f : {ShadingFrequency::pixel, ShadingFrequency::vertex}) {
    if (name == to_string(f)) {
      frequency = f;
      return true;
    }
  }
  return false;
}

bool operator==(const RasterSettings& a, const RasterSettings& b) {
  return a.shading == b.shading && a.shadow_map_size == b.shadow_map_size &&
         a.shadow_bias == b.shadow_bias;
}

}  // namespace gloss

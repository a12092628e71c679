// The script lines of the viewport's renderer and pointer (docs/editor.md, "Scripted mode"):
// the raster (GLSL) path's knobs (issue 12) and mouse gestures. Split from script.cpp, which
// parses the document's lines.
#include <cmath>
#include <string>

#include "editor/model/script/script_tokens.h"

namespace gloss {

// `mouse press X Y [left|right|middle]`, `mouse move X Y`, `mouse release` (script.h).
MouseAction parse_mouse(Tokens& t) {
  MouseAction a;
  const std::string& what = t.word("mouse action");
  if (what == "release") {
    a.verb = MouseAction::Verb::release;
    return a;
  }
  if (what != "press" && what != "move") {
    throw std::runtime_error(
        "mouse must be 'press X Y [left|right|middle]', 'move X Y' or "
        "'release', got '" +
        what + "'");
  }
  a.verb = what == "press" ? MouseAction::Verb::press : MouseAction::Verb::move;
  a.x = t.number("x (0..1 of the viewport image)");
  a.y = t.number("y (0..1 of the viewport image)");
  if (!(a.x >= 0.0f && a.x <= 1.0f && a.y >= 0.0f && a.y <= 1.0f)) {
    throw std::runtime_error("mouse x and y are fractions of the viewport image, 0..1");
  }
  if (a.verb == MouseAction::Verb::press && !t.done()) {
    const std::string& button = t.word("mouse button");
    if (button == "left") {
      a.button = 0;
    } else if (button == "right") {
      a.button = 1;
    } else if (button == "middle") {
      a.button = 2;
    } else {
      throw std::runtime_error("mouse button must be left, right or middle, got '" + button + "'");
    }
  }
  return a;
}

// ---- The GLSL path (issue 12): renderer choice and raster knobs ----
// `renderer cpu|gl|auto`, `shading pixel|vertex`, `shadow-map SIZE`, `shadow-bias TEXELS`;
// false when verb is none of them.
bool parse_raster_line(Tokens& t, const std::string& verb, ScriptAction& out) {
  if (verb == "renderer") {
    RendererAction a;
    const std::string& name = t.word("renderer");
    if (!parse_renderer_choice(name, a.choice)) {
      throw std::runtime_error("renderer must be cpu, gl or auto, got '" + name + "'");
    }
    out = a;
    return true;
  }
  if (verb == "shading") {
    ShadingAction a;
    const std::string& name = t.word("shading frequency");
    if (!parse_shading_frequency(name, a.frequency)) {
      throw std::runtime_error("shading must be pixel or vertex, got '" + name + "'");
    }
    out = a;
    return true;
  }
  if (verb == "shadow-map") {
    const double size = t.whole("shadow map size");
    if (size < kMinShadowMapSize || size > kMaxShadowMapSize) {
      throw std::runtime_error("shadow-map must be " + std::to_string(kMinShadowMapSize) + ".." +
                               std::to_string(kMaxShadowMapSize) + " texels");
    }
    out = ShadowMapAction{static_cast<int>(size)};
    return true;
  }
  if (verb == "shadow-bias") {
    const float texels = t.number("shadow bias in texels");
    if (!(texels >= 0.0f) || !std::isfinite(texels)) {
      throw std::runtime_error("shadow-bias must be a finite number of texels >= 0");
    }
    out = ShadowBiasAction{texels};
    return true;
  }
  return false;
}

}  // namespace gloss

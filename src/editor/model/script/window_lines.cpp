// The script lines of the window around the document (issue 24; docs/editor.md, "Scripted
// mode"): the layout and the lobe view's plots. `key KEYS` is parsed in script.cpp.
#include <cmath>
#include <string>

#include "editor/model/script/script_tokens.h"
#include "io/material/preset_table.h"

namespace gloss {

// `lobe plot NAME`, `lobe overlay none|snapshot|material NAME|preset NAME`, `lobe turn A T`.
ScriptAction parse_lobe(Tokens& t) {
  LobeAction a;
  const std::string& what = t.word("lobe action (plot, overlay or turn)");
  if (what == "plot") {
    const std::string& name = t.word("plot");
    if (!parse_lobe_plot(name, a.plot)) {
      throw std::runtime_error("lobe plot must be plane, 3d or albedo, got '" + name + "'");
    }
    return a;
  }
  if (what == "turn") {
    a.verb = LobeAction::Verb::turn;
    a.azimuth_deg = t.number("azimuth degrees");
    a.tilt_deg = t.number("tilt degrees");
    if (!(a.tilt_deg >= -10.0f && a.tilt_deg <= 89.0f) || !std::isfinite(a.azimuth_deg)) {
      throw std::runtime_error("lobe turn takes an azimuth and a tilt of -10..89 degrees");
    }
    return a;
  }
  if (what != "overlay") {
    throw std::runtime_error("lobe takes plot, overlay or turn, got '" + what + "'");
  }
  a.verb = LobeAction::Verb::overlay;
  const std::string& kind = t.word("overlay (none, snapshot, material NAME, preset NAME)");
  if (kind == "none") return a;
  if (kind == "snapshot") {
    a.overlay = LobeOverlay::snapshot;
    return a;
  }
  if (kind != "material" && kind != "preset") {
    throw std::runtime_error(
        "lobe overlay takes none, snapshot, 'material NAME' or 'preset NAME', "
        "got '" +
        kind + "'");
  }
  a.overlay = kind == "material" ? LobeOverlay::material : LobeOverlay::preset;
  a.name = t.word("name");
  if (a.overlay == LobeOverlay::preset && find_preset(a.name) == nullptr) {
    throw std::runtime_error("no preset '" + a.name + "'");
  }
  return a;
}

// `layout`, `layout maximise on|off`, `layout collapse|expand left|right`, `layout reset`.
ScriptAction parse_layout(Tokens& t) {
  LayoutAction a;
  if (t.done()) return a;
  const std::string& what = t.word("layout action");
  if (what == "maximise") {
    a.verb = LayoutAction::Verb::maximise;
    a.on = t.on_off("layout maximise");
  } else if (what == "collapse" || what == "expand") {
    a.verb = what == "collapse" ? LayoutAction::Verb::collapse : LayoutAction::Verb::expand;
    const std::string& side = t.word("left or right");
    if (side != "left" && side != "right") {
      throw std::runtime_error("layout " + what + " takes left or right, got '" + side + "'");
    }
    a.right = side == "right";
  } else if (what == "reset") {
    a.verb = LayoutAction::Verb::reset;
  } else {
    throw std::runtime_error(
        "layout takes nothing, 'maximise on|off', 'collapse left|right', 'expand left|right' or "
        "'reset', got '" +
        what + "'");
  }
  return a;
}

}  // namespace gloss

#include "editor/model/script/script.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "base/atomic_file.h"
#include "base/error.h"
#include "editor/model/export/shown_image.h"
#include "editor/model/script/script_tokens.h"

namespace gloss {

namespace {

// `quality raster PATH [WIDTH HEIGHT [REFERENCE_SPP]]` (issue 12: the raster path's rows).
QualityAction parse_quality_raster(Tokens& t) {
  QualityAction q{QualityAction::Verb::raster, t.word("csv path")};
  if (t.done()) return q;
  q.width = t.index("width");
  q.height = t.index("height");
  if (q.width < 1 || q.height < 1 || q.width > kMaxImageSide || q.height > kMaxImageSide) {
    throw std::runtime_error("quality raster: width and height must be 1.." +
                             std::to_string(kMaxImageSide));
  }
  if (t.done()) return q;
  q.reference_spp = t.index("reference spp");
  if (q.reference_spp < 1 || q.reference_spp > kMaxSpp) {
    throw std::runtime_error("quality raster: reference spp must be 1.." + std::to_string(kMaxSpp));
  }
  return q;
}

// "KEY VALUE..." of a part's table, as a SetField.
template <class S>
Command parse_field(Tokens& t, const FieldTable<S>& table, FieldPart part, int index,
                    const std::string& key) {
  const Field<S>* field = find_field(table, key);
  if (field == nullptr) {
    std::string keys;
    for (const Field<S>& f : table) keys += (keys.empty() ? "" : ", ") + std::string(f.key);
    throw std::runtime_error("unknown " + std::string(to_string(part)) + " field '" + key + "' (" +
                             keys + ")");
  }
  return SetField{part, index, field->key, parse_value(t, *field)};
}

ScriptAction parse_light(Tokens& t) {
  if (t.words.size() > 1 && t.words[1] == "add") {
    ++t.next;
    return Command(AddLight{});
  }
  if (t.words.size() > 1 && t.words[1] == "remove") {
    ++t.next;
    return Command(RemoveLight{t.index("light index")});
  }
  const int light = t.index("light index");
  return parse_field(t, light_fields(), FieldPart::light, light, t.word("light field"));
}

// `environment FILE|NAME|off`, `environment rotation DEG`, `environment intensity X`,
// `environment background on|off` (or any key of the environment's table).
ScriptAction parse_environment(Tokens& t) {
  const std::string& what = t.word("environment file, name, off or field");
  if (what == "off" || what == "none") return Command(SetEnvironment{});
  if (what == "background") {
    return parse_field(t, environment_fields(), FieldPart::environment, 0, "as_background");
  }
  if (find_field(environment_fields(), what) != nullptr) {
    return parse_field(t, environment_fields(), FieldPart::environment, 0, what);
  }
  return Command(SetEnvironment{what});
}

// Shorter spellings of render fields, kept working: `shadows on`, `energy on`, `spp 16`,
// `encoding srgb`, `exposure STOPS` (once a view preference, now the document's render.exposure),
// `tone aces`.
ScriptAction parse_render_alias(Tokens& t, const std::string& verb) {
  if (verb == "energy")
    return parse_field(t, render_fields(), FieldPart::render, 0, "energy_normalize");
  if (verb == "encoding") {
    const std::string& e = t.word("encoding");
    if (e != "clamp" && e != "srgb") throw std::runtime_error("encoding must be clamp or srgb");
    FieldValue value;
    value.x = e == "srgb" ? 1.0 : 0.0;
    return Command(SetField{FieldPart::render, 0, "srgb", value});
  }
  return parse_field(t, render_fields(), FieldPart::render, 0, verb);
}

// ---- Exposure and snapshot comparison (issue 13, items 3 and 4) ----
// `view clipped on|off` and `view ab [snapshot]`; false when mode is another view.
bool parse_view_extra(Tokens& t, const std::string& mode, ScriptAction& out) {
  if (mode == "clipped") {
    out = ClippedOverlayAction{t.on_off("view clipped")};
    return true;
  }
  if (mode == "uv_checker") {
    out = UvCheckerAction{t.on_off("view uv_checker")};
    return true;
  }
  if (mode == "ab") {
    ViewAction v;
    v.mode = ViewMode::ab;
    if (!t.done()) {
      const std::string& source = t.word("A/B source");
      if (source == "snapshot") {
        v.ab_source = AbSource::snapshot;
      } else if (source == "cpu-gl") {
        v.ab_source = AbSource::cpu_gl;
      } else if (source == "pixel-vertex") {
        v.ab_source = AbSource::pixel_vertex;
      } else if (source == "reference") {
        v.ab_source = AbSource::reference;
      } else {
        throw std::runtime_error(
            "view ab takes nothing, 'snapshot', 'cpu-gl', 'pixel-vertex' or 'reference', got '" +
            source + "'");
      }
    }
    out = v;
    return true;
  }
  return false;
}

// `view lobe [ELEVATION_DEG] [log|linear]` and `inspect X Y` (the lobe view and the pixel
// inspector).
ScriptAction parse_lobe_elevation(Tokens& t, ViewAction v) {
  const std::string& first = t.words[t.next];
  if (first != "log" && first != "linear") {
    const float degrees = t.number("light elevation in degrees");
    if (!(degrees >= 0.0f && degrees <= 90.0f)) {
      throw std::runtime_error("the light elevation must be 0..90 degrees");
    }
    v.lobe_elevation_deg = degrees;
  }
  if (!t.done()) {
    const std::string& radius = t.word("radius scale");
    if (radius != "log" && radius != "linear") {
      throw std::runtime_error("the lobe's radius is log or linear, got '" + radius + "'");
    }
    v.lobe_log_radius = radius == "log" ? 1 : 0;
  }
  return v;
}

ScriptAction parse_inspect(Tokens& t) {
  InspectAction a;
  a.x = t.index("pixel x");
  a.y = t.index("pixel y");
  return a;
}

ScriptAction parse_line(Tokens& t) {
  const std::string& verb = t.words[0];
  // `preset OBJECT NAME`, `set OBJECT FIELD VALUE...`: an object named by its name is found when
  // the line runs (object_line_command), as for the object lines.
  if (verb == "preset") {
    ObjectLineAction a;
    a.object = parse_object_ref(t);
    a.verb = ObjectLineAction::Verb::preset;
    a.text = t.word("preset name");
    if (a.object.index >= 0) return Command(ApplyPreset{a.object.index, a.text});
    return a;
  }
  if (verb == "set") {
    ObjectLineAction a;
    a.object = parse_object_ref(t);
    a.verb = ObjectLineAction::Verb::field;
    a.field = std::get<SetField>(parse_field(t, material_fields(), FieldPart::material,
                                             std::max(a.object.index, 0), t.word("field")));
    if (a.object.index >= 0) return Command(a.field);
    return a;
  }
  if (verb == "model") {
    SetModel c;
    const std::string& name = t.word("model");
    if (!parse_shading_model(name, c.model)) {
      throw std::runtime_error("model must be phong or blinn-phong, got '" + name + "'");
    }
    if (!t.done()) {
      if (t.word("option") != "keep-size") throw std::runtime_error("expected 'keep-size'");
      c.keep_highlight_size = true;
    }
    return Command(c);
  }
  if (verb == "light") return parse_light(t);
  if (verb == "environment") return parse_environment(t);
  // Issue 24: objects by index or name, material names (script_objects.cpp).
  if (verb == "object" || verb == "material" || verb == "assign" || verb == "save" ||
      verb == "browse" || verb == "gizmo") {
    return parse_object_line(t);
  }
  if (verb == "tessellation") {  // every teapot's segments per patch side; the command checks it
    return Command(SetTessellation{static_cast<int>(t.whole("segments per patch side"))});
  }
  if (verb == "camera") {
    const std::string& what = t.word("camera action or field");
    if (what != "orbit") return parse_field(t, camera_fields(), FieldPart::camera, 0, what);
    const float yaw = t.number("degrees about up");
    return Command(OrbitCamera{yaw, t.number("degrees about right")});
  }
  if (verb == "render")
    return parse_field(t, render_fields(), FieldPart::render, 0, t.word("field"));
  if (verb == "scene") return parse_field(t, scene_fields(), FieldPart::scene, 0, t.word("field"));
  if (find_field(scene_fields(), verb) != nullptr) {  // `ambient R G B`, `background R G B`
    return parse_field(t, scene_fields(), FieldPart::scene, 0, verb);
  }
  if (verb == "shadows" || verb == "energy" || verb == "spp" || verb == "encoding" ||
      verb == "exposure" || verb == "tone") {
    return parse_render_alias(t, verb);
  }
  if (verb == "undo") return UndoAction{};
  if (verb == "redo") return RedoAction{};
  if (verb == "wait") {
    if (t.done()) return WaitAction{};
    const double seconds = t.number("timeout seconds");
    if (!(seconds > 0.0) || !std::isfinite(seconds)) {
      throw std::runtime_error("wait: the timeout must be a finite number of seconds > 0");
    }
    return WaitAction{seconds};
  }
  if (verb == "screenshot") {
    ScreenshotAction s;
    s.path = t.word("path");
    if (!t.done()) {
      const std::string& kind = t.word("kind");
      if (!parse_screenshot_kind(kind, s.kind)) {
        throw std::runtime_error(
            "screenshot kind must be viewport, terms, window, shown or exr, got '" + kind + "'");
      }
    }
    if (s.kind == ScreenshotKind::shown && !shown_path_ok(s.path)) {
      throw std::runtime_error(
          "a shown screenshot is written as .png or .pfm (or into a folder), "
          "got '" +
          s.path + "'");
    }
    return s;
  }
  if (verb == "view") {
    ViewAction v;
    const std::string& mode = t.word("view");
    if (ScriptAction exposure_or_ab; parse_view_extra(t, mode, exposure_or_ab)) {
      return exposure_or_ab;
    }
    if (mode == "term") {
      v.mode = ViewMode::single;
      const std::string& term = t.word("term");
      if (!parse_term_view(term, v.term)) throw std::runtime_error("unknown term '" + term + "'");
    } else if (!parse_view_mode(mode, v.mode) || v.mode == ViewMode::single) {
      throw std::runtime_error(
          "view must be render, terms, ab, lobe, 'term NAME', "
          "'ab snapshot|cpu-gl|pixel-vertex|reference', 'clipped on|off' or "
          "'uv_checker on|off', got '" +
          mode + "'");
    }
    if (v.mode == ViewMode::lobe && !t.done()) return parse_lobe_elevation(t, v);
    return v;
  }
  if (verb == "inspect") return parse_inspect(t);
  if (verb == "reference") return parse_reference(t);
  if (verb == "fit") return parse_fit(t);
  if (verb == "select") {
    const ObjectRef ref = parse_object_ref(t);
    return SelectAction{std::max(ref.index, 0), ref.index < 0 ? ref.name : std::string()};
  }
  if (verb == "stats") return StatsAction{};
  if (verb == "sleep") {
    const float seconds = t.number("seconds");
    if (!(seconds >= 0.0f && seconds <= 3600.0f)) throw std::runtime_error("sleep 0..3600 s");
    return SleepAction{seconds};
  }
  if (verb == "animate") return AnimateAction{t.on_off("animate")};
  if (verb == "quit") return QuitAction{};
  if (verb == "snapshot") return SnapshotAction{};
  if (verb == "quality") {
    const std::string& what = t.word("quality action");
    if (what == "measure") return QualityAction{QualityAction::Verb::measure, ""};
    if (what == "start") return QualityAction{QualityAction::Verb::start, ""};
    if (what == "cancel") return QualityAction{QualityAction::Verb::cancel, ""};
    if (what == "csv") return QualityAction{QualityAction::Verb::csv, t.word("csv path")};
    if (what == "raster") return parse_quality_raster(t);
    throw std::runtime_error(
        "quality must be measure, start, cancel, 'csv PATH' or 'raster PATH', got '" + what + "'");
  }
  if (ScriptAction raster; parse_raster_line(t, verb, raster)) return raster;
  if (verb == "mouse") return parse_mouse(t);
  if (verb == "layout") return parse_layout(t);
  if (verb == "lobe") return parse_lobe(t);
  if (verb == "key") return KeyAction{t.word("keys, as the help window writes them")};
  // Issue 14: the memory report.
  if (verb == "memory") return MemoryAction{};
  // Issue 12: the GLSL path.
  if (verb == "export") {
    const std::string& what = t.word("export kind");
    if (what == "gltf") {
      ExportGltfAction e;
      e.path = t.word("glTF path");
      return e;
    }
    if (what != "glsl") {
      throw std::runtime_error("export must be 'glsl PATH' or 'gltf PATH', got '" + what + "'");
    }
    ExportGlslAction e;
    e.path = t.word("shader path");
    if (!t.done()) e.object = t.index("object index");
    return e;
  }
  throw std::runtime_error("unknown command '" + verb + "'");
}

}  // namespace

Script parse_script(const std::string& text, const std::string& file) {
  Script script;
  script.file = file;
  std::istringstream in(text);
  std::string raw;
  for (int number = 1; std::getline(in, raw); ++number) {
    std::string line;
    try {
      Tokens t = split_words(raw, line);
      if (t.words.empty()) continue;
      ScriptAction action = parse_line(t);
      t.end();
      script.lines.push_back({number, line, std::move(action)});
    } catch (const std::runtime_error& e) {
      throw InputError(file, e.what(), number);
    }
  }
  return script;
}

Tokens split_words(const std::string& line, std::string& text) {
  Tokens t;
  std::string word;
  bool in_word = false, in_quotes = false, quoted = false;
  std::size_t i = 0;
  auto finish = [&] {
    if (in_word) {
      t.words.push_back(word);
      t.quoted.push_back(quoted);
    }
    word.clear();
    in_word = quoted = false;
  };
  for (; i < line.size(); ++i) {
    const char c = line[i];
    if (in_quotes) {
      if (c == '\\' && i + 1 < line.size() && (line[i + 1] == '"' || line[i + 1] == '\\')) {
        word += line[++i];
      } else if (c == '"') {
        in_quotes = false;
      } else {
        word += c;
      }
    } else if (c == '#') {
      break;
    } else if (c == '"') {
      in_quotes = in_word = quoted = true;
    } else if (c == ' ' || c == '\t' || c == '\r') {
      finish();
    } else {
      word += c;
      in_word = true;
    }
  }
  if (in_quotes) throw std::runtime_error("a quote is not closed");
  finish();
  text = line.substr(0, i);
  return t;
}

Script load_script(const std::string& path) {
  return parse_script(read_text_file(path), path);
}

}  // namespace gloss

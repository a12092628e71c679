#include "editor/model/script.h"

#include <cstdlib>
#include <sstream>

#include "base/atomic_file.h"
#include "base/error.h"
#include "editor/model/command_layer.h"

namespace gloss {

namespace {

// Tokens of one line and the parsing helpers that turn them into values, throwing plain
// messages that parse_script turns into InputErrors with the line number.
struct Tokens {
  std::vector<std::string> words;
  std::size_t next = 1;  // words[0] is the command

  bool done() const { return next >= words.size(); }
  const std::string& word(const char* what) {
    if (done()) throw std::runtime_error(std::string("missing ") + what);
    return words[next++];
  }
  float number(const char* what) {
    const std::string& w = word(what);
    char* end = nullptr;
    const float value = std::strtof(w.c_str(), &end);
    if (end == w.c_str() || *end != '\0') {
      throw std::runtime_error(std::string("expected a number for ") + what + ", got '" + w + "'");
    }
    return value;
  }
  int index(const char* what) {
    const std::string& w = word(what);
    char* end = nullptr;
    const long value = std::strtol(w.c_str(), &end, 10);
    if (end == w.c_str() || *end != '\0' || value < 0 || value > 1000000) {
      throw std::runtime_error(std::string("expected an index for ") + what + ", got '" + w + "'");
    }
    return static_cast<int>(value);
  }
  glm::vec3 vec3(const char* what) {
    const float x = number(what);
    const float y = number(what);
    const float z = number(what);
    return {x, y, z};
  }
  bool on_off(const char* what) {
    const std::string& w = word(what);
    if (w == "on") return true;
    if (w == "off") return false;
    throw std::runtime_error(std::string(what) + " must be on or off, got '" + w + "'");
  }
  void end() {
    if (!done()) throw std::runtime_error("unexpected '" + words[next] + "'");
  }
};

ScriptAction parse_set(Tokens& t) {
  const int object = t.index("object index");
  const std::string& field_name = t.word("field");
  MaterialField field;
  if (!parse_material_field(field_name, field)) {
    throw std::runtime_error("unknown field '" + field_name +
                             "' (ambient, diffuse, specular, emission, shininess)");
  }
  if (field == MaterialField::shininess) return Command(SetShininess{object, t.number("value")});
  // One number sets a grey colour, three set R G B.
  const float r = t.number("colour");
  if (t.done()) return Command(SetMaterialColour{object, field, glm::vec3(r)});
  const float g = t.number("colour");
  const float b = t.number("colour");
  return Command(SetMaterialColour{object, field, {r, g, b}});
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
  const std::string& field_name = t.word("light field");
  LightField field;
  if (!parse_light_field(field_name, field)) {
    throw std::runtime_error("unknown light field '" + field_name +
                             "' (position, ambient, diffuse, specular, attenuation)");
  }
  return Command(SetLightValue{light, field, t.vec3("light value")});
}

ScriptAction parse_line(Tokens& t) {
  const std::string& verb = t.words[0];
  if (verb == "preset") {
    const int object = t.index("object index");
    return Command(ApplyPreset{object, t.word("preset name")});
  }
  if (verb == "set") return parse_set(t);
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
  if (verb == "camera") {
    if (t.word("camera action") != "orbit") throw std::runtime_error("expected 'camera orbit'");
    const float yaw = t.number("degrees about up");
    return Command(OrbitCamera{yaw, t.number("degrees about right")});
  }
  if (verb == "ambient") return Command(SetSceneAmbient{t.vec3("ambient")});
  if (verb == "background") return Command(SetBackground{t.vec3("background")});
  if (verb == "shadows") return Command(SetShadows{t.on_off("shadows")});
  if (verb == "energy") return Command(SetEnergyNormalize{t.on_off("energy")});
  if (verb == "spp") return Command(SetTargetSpp{t.index("spp")});
  if (verb == "undo") return UndoAction{};
  if (verb == "redo") return RedoAction{};
  if (verb == "wait") return t.done() ? WaitAction{} : WaitAction{t.number("timeout seconds")};
  if (verb == "screenshot") {
    ScreenshotAction s;
    s.path = t.word("path");
    if (!t.done()) {
      const std::string& kind = t.word("kind");
      if (!parse_screenshot_kind(kind, s.kind)) {
        throw std::runtime_error("screenshot kind must be viewport, terms or window, got '" + kind +
                                 "'");
      }
    }
    return s;
  }
  if (verb == "view") {
    ViewAction v;
    const std::string& mode = t.word("view");
    if (mode == "term") {
      v.mode = ViewMode::single;
      const std::string& term = t.word("term");
      if (!parse_term_view(term, v.term)) throw std::runtime_error("unknown term '" + term + "'");
    } else if (!parse_view_mode(mode, v.mode) || v.mode == ViewMode::single) {
      throw std::runtime_error("view must be render, terms, ab or 'term NAME', got '" + mode + "'");
    }
    return v;
  }
  if (verb == "exposure") return ExposureAction{t.number("stops")};
  if (verb == "encoding") {
    const std::string& e = t.word("encoding");
    if (e != "clamp" && e != "srgb") throw std::runtime_error("encoding must be clamp or srgb");
    return EncodingAction{e == "srgb"};
  }
  if (verb == "select") return SelectAction{t.index("object index")};
  if (verb == "stats") return StatsAction{};
  if (verb == "sleep") {
    const float seconds = t.number("seconds");
    if (!(seconds >= 0.0f && seconds <= 3600.0f)) throw std::runtime_error("sleep 0..3600 s");
    return SleepAction{seconds};
  }
  if (verb == "animate") return AnimateAction{t.on_off("animate")};
  if (verb == "quit") return QuitAction{};
  if (verb == "quality") {
    const std::string& what = t.word("quality action");
    if (what == "measure") return QualityAction{QualityAction::Verb::measure, ""};
    if (what == "start") return QualityAction{QualityAction::Verb::start, ""};
    if (what == "cancel") return QualityAction{QualityAction::Verb::cancel, ""};
    if (what == "csv") return QualityAction{QualityAction::Verb::csv, t.word("csv path")};
    throw std::runtime_error("quality must be measure, start, cancel or 'csv PATH', got '" + what +
                             "'");
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
    std::string line = raw.substr(0, raw.find('#'));
    Tokens t;
    std::istringstream words(line);
    for (std::string w; words >> w;) t.words.push_back(w);
    if (t.words.empty()) continue;
    try {
      ScriptAction action = parse_line(t);
      t.end();
      script.lines.push_back({number, line, std::move(action)});
    } catch (const std::runtime_error& e) {
      throw InputError(file, e.what(), number);
    }
  }
  return script;
}

Script load_script(const std::string& path) {
  return parse_script(read_text_file(path), path);
}

bool run_document_line(const ScriptLine& line, CommandLayer& layer, const std::string& file) {
  try {
    if (const Command* command = std::get_if<Command>(&line.action)) {
      layer.execute(*command);
      layer.seal();
      return true;
    }
    if (std::holds_alternative<UndoAction>(line.action)) {
      if (!layer.undo()) throw CommandError("nothing to undo");
      return true;
    }
    if (std::holds_alternative<RedoAction>(line.action)) {
      if (!layer.redo()) throw CommandError("nothing to redo");
      return true;
    }
  } catch (const CommandError& e) {
    throw InputError(file, e.what(), line.line);
  }
  return false;
}

}  // namespace gloss

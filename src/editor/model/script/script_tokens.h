#pragma once
// The words of one script line and the helpers that turn them into values (private to
// editor/model/script): script.cpp parses most lines with them, reference_lines.cpp the physical
// reference's, script_objects.cpp the objects'. Words are separated by blanks; a word in double
// quotes may hold blanks
// ("gold ball"; \" and \\ inside stand for " and \); '#' outside quotes starts a comment. The
// helpers throw plain messages that parse_script turns into errors naming the file and line.
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "editor/model/script/script.h"

namespace gloss {

// Tokens of one line and the parsing helpers that turn them into values, throwing plain
// messages that parse_script turns into InputErrors with the line number.
struct Tokens {
  std::vector<std::string> words;
  std::vector<bool> quoted;  // parallel to words: the word was written in quotes
  std::size_t next = 1;      // words[0] is the command

  bool done() const { return next >= words.size(); }
  const std::string& word(const char* what) {
    if (done()) throw std::runtime_error(std::string("missing ") + what);
    return words[next++];
  }
  // No hexadecimal ("0x10" read as 16 by strtof and strtod): a scene file's JSON has none. inf
  // and nan pass on to the fields' own checks, which name the field.
  static bool hexadecimal(const std::string& w) {
    return w.find_first_of("xX") != std::string::npos;
  }
  float number(const char* what) {
    const std::string& w = word(what);
    char* end = nullptr;
    const float value = std::strtof(w.c_str(), &end);
    if (end == w.c_str() || *end != '\0' || hexadecimal(w)) {
      throw std::runtime_error(std::string("expected a number for ") + what + ", got '" + w + "'");
    }
    return value;
  }
  double whole(const char* what) {
    const std::string& w = word(what);
    char* end = nullptr;
    const double value = std::strtod(w.c_str(), &end);
    if (end == w.c_str() || *end != '\0' || value != std::floor(value) || hexadecimal(w)) {
      throw std::runtime_error(std::string("expected a whole number for ") + what + ", got '" + w +
                               "'");
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

// A map: `PATH [wrap MODE | wrap U_MODE V_MODE] [scale S | scale SU SV] [offset DU DV]
// [rotation DEGREES] [uv_set 0|1]`, or `none` to clear the slot. The path is one word, relative
// to the scene's folder; the image is read when the line runs (document/command.cpp).
inline TextureMap parse_map(Tokens& t, const char* key) {
  TextureMap map;
  const std::string file = t.word(key);
  if (file == "none") return map;
  map.file = file;
  auto wrap = [](const std::string& name) {
    if (name == "repeat") return Wrap::repeat;
    if (name == "clamp") return Wrap::clamp;
    if (name == "mirror") return Wrap::mirror;
    throw std::runtime_error("wrap must be repeat, clamp or mirror, got '" + name + "'");
  };
  auto numeric = [](const std::string& w) {
    char* end = nullptr;
    std::strtof(w.c_str(), &end);
    return end != w.c_str() && *end == '\0';
  };
  while (!t.done()) {
    const std::string option = t.word("map option");
    if (option == "wrap") {
      map.wrap[0] = map.wrap[1] = wrap(t.word("wrap mode"));
      if (!t.done() && t.words[t.next] != "scale" && t.words[t.next] != "offset" &&
          t.words[t.next] != "rotation" && t.words[t.next] != "uv_set") {
        map.wrap[1] = wrap(t.word("wrap mode"));
      }
    } else if (option == "scale") {
      map.scale = glm::vec2(t.number("scale"));
      if (!t.done() && numeric(t.words[t.next])) map.scale.y = t.number("scale");
    } else if (option == "offset") {
      map.offset.x = t.number("offset");
      map.offset.y = t.number("offset");
    } else if (option == "rotation") {
      map.rotation = t.number("rotation");
    } else if (option == "uv_set") {
      map.uv_set = t.index("uv_set");
    } else {
      throw std::runtime_error("unknown map option '" + option +
                               "' (wrap, scale, offset, rotation, uv_set)");
    }
  }
  return map;
}

// A value of field from the rest of the line: one number for a grey colour or three for R G B,
// three for a vector (or one, for a vector that takes one number), one number, a whole number,
// on/off, a map, or a choice's name.
template <class S>
FieldValue parse_value(Tokens& t, const Field<S>& field) {
  FieldValue value;
  switch (field.kind) {
    case FieldKind::colour: {
      const float r = t.number("colour");
      if (t.done()) {
        value.v = glm::vec3(r);
        break;
      }
      const float g = t.number("colour");
      value.v = {r, g, t.number("colour")};
      break;
    }
    case FieldKind::vector:
      if (field.one_number) {  // `scale 2` for 2 2 2
        const float x = t.number(field.key);
        if (t.done()) {
          value.v = glm::vec3(x);
          break;
        }
        const float y = t.number(field.key);
        value.v = glm::vec3(x, y, t.number(field.key));
        break;
      }
      value.v = t.vec3(field.key);
      break;
    case FieldKind::number:
      value.x = t.number(field.key);
      break;
    case FieldKind::whole:
      value.x = t.whole(field.key);
      break;
    case FieldKind::flag:
      value.x = t.on_off(field.key) ? 1.0 : 0.0;
      break;
    case FieldKind::map:
      value.map = parse_map(t, field.key);
      break;
    case FieldKind::choice: {
      const std::string& name = t.word(field.key);
      const int index = choice_index(field, name);
      if (index < 0) {
        std::string names;
        for (const char* c : field.choices) names += (names.empty() ? "" : ", ") + std::string(c);
        throw std::runtime_error(std::string(field.key) + " must be one of " + names + ", got '" +
                                 name + "'");
      }
      value.x = index;
      break;
    }
  }
  return value;
}

// The words of line (comment dropped). Throws for a quote that is not closed.
// text: the line without its comment.
Tokens split_words(const std::string& line, std::string& text);

// `reference METAL ROUGHNESS`, `reference dielectric R G B ROUGHNESS`, `reference none`
// (reference_lines.cpp).
ScriptAction parse_reference(Tokens& t);
// `fit phong|blinn-phong [l2|lightness]` (reference_lines.cpp).
ScriptAction parse_fit(Tokens& t);

// An object named by the next word: a bare whole number is an index, any other word (or a quoted
// one) a name (script_objects.cpp).
ObjectRef parse_object_ref(Tokens& t);

// The object and material lines (script_objects.cpp): `object ...`, `material rename OLD NEW`,
// `assign OBJECT MATERIAL`, and `save PATH`, `browse WHAT`, `gizmo MODE`; t.words[0] is one of
// object, material, assign, save, browse, gizmo.
ScriptAction parse_object_line(Tokens& t);
// viewport_lines.cpp: `mouse press X Y [left|right|middle]`, `mouse move X Y`, `mouse release`;
// and `renderer cpu|gl|auto`, `shading pixel|vertex`, `shadow-map SIZE`, `shadow-bias TEXELS`
// (parse_raster_line: false when verb is none of them).
MouseAction parse_mouse(Tokens& t);
bool parse_raster_line(Tokens& t, const std::string& verb, ScriptAction& out);
// window_lines.cpp: `layout ...` and `lobe plot|overlay|turn ...` (issue 24).
ScriptAction parse_layout(Tokens& t);
ScriptAction parse_lobe(Tokens& t);

}  // namespace gloss

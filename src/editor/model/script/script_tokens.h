#pragma once
// The words of one script line and the helpers that turn them into values (private to
// editor/model/script): script.cpp parses most lines with them, reference_lines.cpp the physical
// reference's. The helpers throw std::runtime_error with plain messages that parse_script turns
// into InputErrors naming the line.
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "editor/model/script/script.h"

namespace gloss {

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
  double whole(const char* what) {
    const std::string& w = word(what);
    char* end = nullptr;
    const double value = std::strtod(w.c_str(), &end);
    if (end == w.c_str() || *end != '\0' || value != std::floor(value)) {
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

// `reference METAL ROUGHNESS`, `reference dielectric R G B ROUGHNESS`, `reference none`
// (reference_lines.cpp).
ScriptAction parse_reference(Tokens& t);
// `fit phong|blinn-phong [l2|lightness]` (reference_lines.cpp).
ScriptAction parse_fit(Tokens& t);

// window_lines.cpp: `layout ...` and `lobe plot|overlay|turn ...` (issue 24).
ScriptAction parse_layout(Tokens& t);
ScriptAction parse_lobe(Tokens& t);

}  // namespace gloss

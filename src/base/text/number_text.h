#pragma once
// A number as messages and reports show it: printf's %g with `digits` significant digits (6,
// %g's own, by default: "0.5", "1e+06", "-2").
#include <cstdio>
#include <string>

namespace gloss {

inline std::string number_text(double value, int digits = 6) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

}  // namespace gloss

#pragma once
// Whole-word numbers for the line-oriented text loaders (OBJ, the teapot's patch file): a word
// is a number only if all of it is.
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

namespace gloss {

inline bool parse_long(const std::string& word, long& out) {
  char* end = nullptr;
  errno = 0;
  out = std::strtol(word.c_str(), &end, 10);
  return errno == 0 && end != word.c_str() && *end == '\0';
}

// A finite float (values beyond float's range are refused, not turned into infinity).
inline bool parse_finite_float(const std::string& word, float& out) {
  char* end = nullptr;
  out = std::strtof(word.c_str(), &end);
  return end != word.c_str() && *end == '\0' && std::isfinite(out);
}

}  // namespace gloss

#pragma once
// The text form of `gloss-cli bench`: one row a figure, laid out alike in every part of the
// report (the engine's, the environment's), so their columns line up.
#include <string>

namespace gloss {

struct BenchTable {
  std::string text;

  // "  name value unit note": the name padded to 30 characters, the value as %10.4f.
  void row(const char* name, double value, const char* unit, const char* note);
  // A free-form line (headers, curves), printf's format; at most 255 characters are kept.
  void line(const char* format, ...) __attribute__((format(printf, 2, 3)));
};

}  // namespace gloss

#include "analysis/bench/bench_table.h"

#include <cstdarg>
#include <cstdio>

namespace gloss {

void BenchTable::row(const char* name, double value, const char* unit, const char* note) {
  line("  %-30s %10.4f %-4s %s\n", name, value, unit, note);
}

void BenchTable::line(const char* format, ...) {
  char buffer[256];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  text += buffer;
}

}  // namespace gloss

#include "base/text/ascii.h"

#include <algorithm>

namespace gloss {

std::string ascii_lower(std::string s) {
  for (char& c : s) c = ascii_lower(c);
  return s;
}

bool ascii_equal_ignoring_case(std::string_view a, std::string_view b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](char x, char y) { return ascii_lower(x) == ascii_lower(y); });
}

std::string lower_extension(const std::filesystem::path& path) {
  return ascii_lower(path.extension().string());
}

}  // namespace gloss

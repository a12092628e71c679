#pragma once
// ASCII case, for what gloss compares without case: file extensions, MTL keywords, shortcut and
// object names typed in a filter. Only A-Z change; every other byte (UTF-8 included) stays as it
// is, whatever the C locale (std::tolower follows it).
#include <filesystem>
#include <string>
#include <string_view>

namespace gloss {

// c with A-Z lower-cased.
constexpr char ascii_lower(char c) {
  return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

// s with A-Z lower-cased.
std::string ascii_lower(std::string s);

// Whether a and b are equal but for the case of A-Z.
bool ascii_equal_ignoring_case(std::string_view a, std::string_view b);

// The extension of path's file name, dot included, A-Z lower-cased: ".glb" for "Box.GLB", ""
// for none.
std::string lower_extension(const std::filesystem::path& path);

}  // namespace gloss

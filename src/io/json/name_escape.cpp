#include "io/json/name_escape.h"

#include "base/text/printable_text.h"

namespace gloss {

namespace {

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// True when text[i] starts "\xHH".
bool escape_at(const std::string& text, std::size_t i) {
  return i + 3 < text.size() && text[i] == '\\' && text[i + 1] == 'x' &&
         hex_value(text[i + 2]) >= 0 && hex_value(text[i + 3]) >= 0;
}

}  // namespace

std::string escape_name(const std::string& name) {
  std::string out;
  out.reserve(name.size());
  std::size_t i = 0;
  while (i < name.size()) {
    const std::size_t length = utf8_sequence_length(name, i);
    if (length == 0 || escape_at(name, i)) {
      append_hex_escape(out, static_cast<unsigned char>(name[i]));
      ++i;
    } else {
      out.append(name, i, length);
      i += length;
    }
  }
  return out;
}

std::string unescape_name(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    if (escape_at(text, i)) {
      out += static_cast<char>(hex_value(text[i + 2]) * 16 + hex_value(text[i + 3]));
      i += 4;
    } else {
      out += text[i++];
    }
  }
  return out;
}

}  // namespace gloss

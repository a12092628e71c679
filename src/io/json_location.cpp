#include "io/json_location.h"

#include "base/error.h"

namespace gloss {

namespace {

// nlohmann's what() is "[json.exception.parse_error.101] parse error at line 1, column 9: MESSAGE";
// the position prefix is dropped because InputError adds its own.
std::string parse_error_message(const nlohmann::json::parse_error& error) {
  const std::string what = error.what();
  const std::size_t colon = what.find(": ");
  return colon == std::string::npos ? what : what.substr(colon + 2);
}

template <class Json>
Json parse_with_location(const std::string& text, const std::string& file) {
  try {
    return Json::parse(text);
  } catch (const nlohmann::json::parse_error& error) {
    // error.byte counts the characters read, 1-based, including the one that failed (an
    // end-of-input read counts too, so truncation points just past the last character).
    const std::size_t offset = error.byte > 0 ? error.byte - 1 : 0;
    int line = 1, column = 1;
    byte_offset_to_line_column(text, offset, line, column);
    throw InputError(file, parse_error_message(error), line, column);
  }
}

}  // namespace

void byte_offset_to_line_column(const std::string& text, std::size_t offset, int& line,
                                int& column) {
  const std::size_t end = offset < text.size() ? offset : text.size();
  line = 1;
  column = 1;
  for (std::size_t i = 0; i < end; ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte == '\n') {
      ++line;
      column = 1;
    } else if ((byte & 0xC0u) != 0x80u) {
      // UTF-8 continuation bytes (10xxxxxx) belong to the character already counted.
      ++column;
    }
  }
}

nlohmann::json parse_json_text(const std::string& text, const std::string& file) {
  return parse_with_location<nlohmann::json>(text, file);
}

nlohmann::ordered_json parse_ordered_json_text(const std::string& text, const std::string& file) {
  return parse_with_location<nlohmann::ordered_json>(text, file);
}

}  // namespace gloss

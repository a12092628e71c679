#include "io/json/json_location.h"

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

// A SAX pass that only records where parsing stops and on which token. A syntax error carries its
// own position; this finds values nlohmann refuses after lexing them, such as 1e400 (number
// overflow, an out_of_range exception without a position).
class ErrorLocator : public nlohmann::json_sax<nlohmann::json> {
 public:
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t position, const std::string& token,
                   const nlohmann::detail::exception&) override {
    // position counts the characters read, up to the end of the offending token.
    start = position >= token.size() ? position - token.size() : 0;
    found = true;
    return false;
  }
  std::size_t start = 0;
  bool found = false;
};

// nlohmann's what() without its "[json.exception.NAME.ID] " prefix.
std::string library_message(const nlohmann::json::exception& error) {
  const std::string what = error.what();
  const std::size_t prefix = what.find("] ");
  return prefix == std::string::npos ? what : what.substr(prefix + 2);
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
  } catch (const nlohmann::json::exception& error) {
    // Any other library exception (a number out of range) becomes an InputError too, at the
    // token the SAX pass stops on.
    ErrorLocator locator;
    nlohmann::json::sax_parse(text, &locator);
    int line = 0, column = 0;
    if (locator.found) byte_offset_to_line_column(text, locator.start, line, column);
    throw InputError(file, library_message(error), line, column);
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

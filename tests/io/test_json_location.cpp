#include "io/json/json_location.h"

#include <gtest/gtest.h>

#include "base/error.h"

namespace gloss {
namespace {

struct Position {
  int line = 0, column = 0;
};

Position position_of(const std::string& text, std::size_t offset) {
  Position p;
  byte_offset_to_line_column(text, offset, p.line, p.column);
  return p;
}

// The error a parse throws; fails the test when nothing is thrown.
InputError parse_error_of(const std::string& text) {
  try {
    parse_json_text(text, "scene.json");
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no InputError for: " << text;
  return InputError("", "");
}

TEST(JsonLocation, OffsetZeroIsLineOneColumnOne) {
  const Position p = position_of("{}", 0);
  EXPECT_EQ(p.line, 1);
  EXPECT_EQ(p.column, 1);
}

TEST(JsonLocation, NewlineStartsNextLineAtColumnOne) {
  // "ab\ncd": 'c' is byte 3, 'd' is byte 4.
  const std::string text = "ab\ncd";
  EXPECT_EQ(position_of(text, 3).line, 2);
  EXPECT_EQ(position_of(text, 3).column, 1);
  EXPECT_EQ(position_of(text, 4).column, 2);
  // The newline itself is the last column of line 1.
  EXPECT_EQ(position_of(text, 2).line, 1);
  EXPECT_EQ(position_of(text, 2).column, 3);
}

TEST(JsonLocation, MultiByteUtf8CharacterCountsAsOneColumn) {
  // "é" is two bytes (C3 A9); 'x' after it is byte 2 but column 2.
  const std::string text = "\xC3\xA9x";
  EXPECT_EQ(position_of(text, 2).column, 2);
}

TEST(JsonLocation, OffsetPastEndIsJustAfterLastCharacter) {
  const Position p = position_of("ab\nc", 100);
  EXPECT_EQ(p.line, 2);
  EXPECT_EQ(p.column, 2);
}

TEST(JsonLocation, ValidTextParses) {
  const nlohmann::json value = parse_json_text(R"({"a": [1, 2]})", "x.json");
  EXPECT_EQ(value["a"][1], 2);
}

TEST(JsonLocation, SyntaxErrorReportsLineAndColumnOfOffendingCharacter) {
  // Line 3 is `  "b": ]`: the ']' is the 8th character.
  const InputError error = parse_error_of("{\n  \"a\": 1,\n  \"b\": ]\n}\n");
  EXPECT_EQ(error.file(), "scene.json");
  EXPECT_EQ(error.line(), 3);
  EXPECT_EQ(error.column(), 8);
  EXPECT_EQ(std::string(error.what()).rfind("scene.json:3:8: ", 0), 0u) << error.what();
  EXPECT_EQ(error.message().find("[json.exception"), std::string::npos) << error.message();
}

TEST(JsonLocation, MissingCommaPointsAtEndOfUnexpectedToken) {
  // `{"a": 1 "b": 2}`: the unexpected token is the string "b" at columns 9..11; the parser has
  // read up to its closing quote, column 11.
  const InputError error = parse_error_of(R"({"a": 1 "b": 2})");
  EXPECT_EQ(error.line(), 1);
  EXPECT_EQ(error.column(), 11);
}

TEST(JsonLocation, TruncatedTextPointsJustPastTheEnd) {
  // Two lines; the second, `"a": 1`, has 6 characters, so the end is column 7.
  const InputError error = parse_error_of("{\n\"a\": 1");
  EXPECT_EQ(error.line(), 2);
  EXPECT_EQ(error.column(), 7);
  EXPECT_NE(error.message().find("end of input"), std::string::npos) << error.message();
}

TEST(JsonLocation, EmptyTextIsAnErrorAtLineOneColumnOne) {
  const InputError error = parse_error_of("");
  EXPECT_EQ(error.line(), 1);
  EXPECT_EQ(error.column(), 1);
}

TEST(JsonLocation, OrderedParseKeepsFileKeyOrder) {
  const nlohmann::ordered_json value = parse_ordered_json_text(R"({"z": 1, "a": 2})", "x.json");
  EXPECT_EQ(value.begin().key(), "z");
}

}  // namespace
}  // namespace gloss

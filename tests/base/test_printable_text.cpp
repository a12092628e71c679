#include "base/text/printable_text.h"

#include <gtest/gtest.h>

#include "base/error.h"

namespace gloss {
namespace {

TEST(PrintableText, KeepsPlainAndMultibyteTextAndBackslashes) {
  EXPECT_EQ(printable_text("Terrain \xC3\xA6k a\\b"), "Terrain \xC3\xA6k a\\b");
}

TEST(PrintableText, EscapesC0ControlsAndDel) {
  EXPECT_EQ(printable_text(std::string("a\x1b[2Jb\r\n\t\x7f", 10)),
            "a\\x1B[2Jb\\x0D\\x0A\\x09\\x7F");
  EXPECT_EQ(printable_text(std::string("\0z", 2)), "\\x00z");
}

TEST(PrintableText, EscapesC1ControlsWrittenAsUtf8) {
  // U+009B is the 8-bit CSI; U+00A0 (no-break space) is the first character after the C1 block.
  EXPECT_EQ(printable_text("x\xC2\x9B"
                           "1m\xC2\xA0"),
            "x\\xC2\\x9B1m\xC2\xA0");
}

TEST(PrintableText, EscapesBytesThatAreNotUtf8) {
  EXPECT_EQ(printable_text("Terrain\xE6k"), "Terrain\\xE6k");             // Latin-1 ae
  EXPECT_EQ(printable_text("\xC0\xAF"), "\\xC0\\xAF");                    // overlong '/'
  EXPECT_EQ(printable_text("\xED\xA0\x80"), "\\xED\\xA0\\x80");           // surrogate U+D800
  EXPECT_EQ(printable_text("\xF4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");  // above U+10FFFF
  EXPECT_EQ(printable_text("\xF0\x9F\x98\x80"), "\xF0\x9F\x98\x80");      // U+1F600 is fine
  EXPECT_EQ(printable_text("\xE2\x82"), "\\xE2\\x82");                    // truncated
}

TEST(PrintableText, Utf8SequenceLengths) {
  EXPECT_EQ(utf8_sequence_length("a", 0), 1u);
  EXPECT_EQ(utf8_sequence_length("\xC3\xA6", 0), 2u);
  EXPECT_EQ(utf8_sequence_length("\xE2\x82\xAC", 0), 3u);
  EXPECT_EQ(utf8_sequence_length("\xF0\x9F\x98\x80", 0), 4u);
  EXPECT_EQ(utf8_sequence_length("\xA6", 0), 0u);
  EXPECT_EQ(utf8_sequence_length("\xE6k", 0), 0u);
}

TEST(ErrorText, InputErrorEscapesControlCharactersFromTheInput) {
  const InputError error("scene\r.json", "unknown material 'red\x1b]0;owned\x07'", 0, 0,
                         "objects[0].material");
  EXPECT_STREQ(error.what(),
               "scene\\x0D.json: objects[0].material: unknown material 'red\\x1B]0;owned\\x07'");
  EXPECT_EQ(error.file(), "scene\r.json");  // the bytes themselves stay available
}

TEST(ErrorText, RuntimeFailureEscapesControlCharacters) {
  const RuntimeFailure error("cannot write out\x1b.png: reason");
  EXPECT_STREQ(error.what(), "cannot write out\\x1B.png: reason");
}

}  // namespace
}  // namespace gloss

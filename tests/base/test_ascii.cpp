// ASCII case: only A-Z change, whatever the bytes around them (UTF-8 names stay as written).
#include "base/text/ascii.h"

#include <string>

#include <gtest/gtest.h>

namespace gloss {
namespace {

TEST(Ascii, OnlyAToZAreLowerCased) {
  EXPECT_EQ(ascii_lower("Map_Kd BUMP -Bm"), "map_kd bump -bm");
  EXPECT_EQ(ascii_lower("@[`{"), "@[`{");  // the bytes either side of A-Z and a-z
  // "Ä" in UTF-8 (0xC3 0x84) and Latin-1 "À" (0xC0): left as they are.
  EXPECT_EQ(ascii_lower("\xC3\x84X\xC0"), "\xC3\x84x\xC0");
  EXPECT_EQ(ascii_lower('Z'), 'z');
  EXPECT_EQ(ascii_lower('z'), 'z');
  EXPECT_EQ(ascii_lower(""), "");
}

TEST(Ascii, EqualIgnoringCaseComparesWholeStrings) {
  EXPECT_TRUE(ascii_equal_ignoring_case("Ctrl+Shift+Z", "ctrl+shift+z"));
  EXPECT_FALSE(ascii_equal_ignoring_case("ctrl+z", "ctrl+z "));
  EXPECT_FALSE(ascii_equal_ignoring_case("\xC3\x84", "\xC3\xA4"));  // Ä and ä: not ASCII
  EXPECT_TRUE(ascii_equal_ignoring_case("", ""));
}

TEST(Ascii, LowerExtensionKeepsTheDot) {
  EXPECT_EQ(lower_extension("models/Box.GLB"), ".glb");
  EXPECT_EQ(lower_extension("a.tar.Gz"), ".gz");
  EXPECT_EQ(lower_extension("Makefile"), "");
  EXPECT_EQ(lower_extension("dir.D/readme"), "");
}

}  // namespace
}  // namespace gloss

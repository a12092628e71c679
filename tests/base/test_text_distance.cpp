#include "base/text/text_distance.h"

#include <gtest/gtest.h>

namespace gloss {
namespace {

TEST(TextDistance, IdenticalWordsAreAtDistanceZero) {
  EXPECT_EQ(edit_distance("diffuse", "diffuse"), 0u);
  EXPECT_EQ(edit_distance("", ""), 0u);
}

TEST(TextDistance, EmptyWordIsAsFarAsTheOtherWordIsLong) {
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("abc", ""), 3u);
}

TEST(TextDistance, CountsInsertionsDeletionsAndSubstitutions) {
  // kitten -> sitten (substitute) -> sittin (substitute) -> sitting (insert).
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  // flaw -> law (delete) -> lawn (insert).
  EXPECT_EQ(edit_distance("flaw", "lawn"), 2u);
  EXPECT_EQ(edit_distance("difuse", "diffuse"), 1u);
  EXPECT_EQ(edit_distance("gld", "gold"), 1u);
}

TEST(TextDistance, IsSymmetric) {
  EXPECT_EQ(edit_distance("shininess", "shine"), edit_distance("shine", "shininess"));
}

TEST(TextDistance, IsCaseSensitive) {
  EXPECT_EQ(edit_distance("Gold", "gold"), 1u);
}

TEST(TextDistance, NearestWordsComeNearestFirst) {
  const std::vector<std::string> keys = {"preset",   "ambient",  "diffuse",
                                         "specular", "emission", "shininess"};
  const std::vector<std::string> nearest = nearest_words("difuse", keys, 1);
  ASSERT_EQ(nearest.size(), 1u);
  EXPECT_EQ(nearest[0], "diffuse");
  EXPECT_EQ(nearest_words("shinyness", keys, 1).front(), "shininess");
}

TEST(TextDistance, NearestWordsReturnsAtMostMaxCount) {
  const std::vector<std::string> words = {"a", "b", "c", "d"};
  EXPECT_EQ(nearest_words("x", words, 2).size(), 2u);
  EXPECT_EQ(nearest_words("x", words, 10).size(), 4u);
  EXPECT_TRUE(nearest_words("x", {}, 3).empty());
}

TEST(TextDistance, EquallyNearWordsKeepTheirGivenOrder) {
  // "cat" is one edit from each of "bat", "cot", "car".
  const std::vector<std::string> nearest = nearest_words("cat", {"dog", "bat", "cot", "car"}, 3);
  EXPECT_EQ(nearest, (std::vector<std::string>{"bat", "cot", "car"}));
}

}  // namespace
}  // namespace gloss

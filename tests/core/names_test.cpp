#include "core/names.hpp"

#include <gtest/gtest.h>

namespace eco {

TEST(Names, CaseIsIgnored) {
  EXPECT_TRUE(sameNameIgnoringCase("Beech", "beech"));
  EXPECT_FALSE(sameNameIgnoringCase("beech", "beeches"));
}

TEST(Names, EditDistanceCountsInsertionsDeletionsAndSubstitutions) {
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);  // the textbook example
  EXPECT_EQ(editDistance("", "pine"), 4u);
  EXPECT_EQ(editDistance("Pine", "pine"), 0u);
  EXPECT_EQ(editDistance("valey", "valley"), 1u);
  EXPECT_EQ(editDistance("mapel", "maple"), 1u);  // a swap is one slip of the fingers
}

TEST(Names, OnlyANearMissIsSuggested) {
  const std::vector<std::string> names{"beech", "birch", "maple", "pine"};
  EXPECT_EQ(closestName("beeh", names), "beech");
  EXPECT_EQ(closestName("mapel", names), "maple");
  EXPECT_EQ(closestName("oak", names), std::nullopt);
  EXPECT_EQ(didYouMean("pne", names), ": did you mean 'pine'?");
  EXPECT_EQ(didYouMean("baobab", names), "");
}

TEST(Names, PlainNamesAreWordsSafeInFileNamesAndCsv) {
  for (const char* good : {"beech", "Pinus_sylvestris", "oak-2", "a"})
    EXPECT_EQ(whyNotAPlainName(good), "") << good;
  EXPECT_EQ(whyNotAPlainName(""), "it is empty");
  EXPECT_EQ(whyNotAPlainName("2pine"), "it must begin with a letter");
  EXPECT_EQ(whyNotAPlainName(std::string(65, 'a')), "it is longer than 64 characters");
  for (const char* bad : {"be,ech", "sub/beech", "two words", "..", "b\"ee", "bu\xc3\x9f" "e"})
    EXPECT_NE(whyNotAPlainName(bad), "") << bad;
}

}  // namespace eco

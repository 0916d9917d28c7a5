#include "core/error.hpp"

#include <gtest/gtest.h>

namespace eco {

TEST(InputError, FormatsFileLineKeyAndMessage) {
  InputError error({"trees/beech.toml", 12, "strand.kd"}, "expected a number");
  EXPECT_STREQ(error.what(), "trees/beech.toml:12: strand.kd: expected a number");
  EXPECT_EQ(error.where().line, 12);
  EXPECT_EQ(error.message(), "expected a number");
}

TEST(InputError, OmitsLineZeroAndEmptyKey) {
  InputError error({"missing.toml", 0, ""}, "cannot open file");
  EXPECT_STREQ(error.what(), "missing.toml: cannot open file");
}

TEST(Assert, ThrowsInternalErrorWithValues) {
  int s0 = 3, s1 = 5;
  try {
    ECO_ASSERT(s1 < s0, "s0=" << s0 << " s1=" << s1);
    FAIL() << "no throw";
  } catch (const InternalError& error) {
    EXPECT_NE(std::string(error.what()).find("s1 < s0"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("s0=3 s1=5"), std::string::npos);
  }
}

}  // namespace eco

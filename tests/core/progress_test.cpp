#include "core/progress.hpp"

#include <gtest/gtest.h>

namespace eco {

TEST(Progress, SilentWhenDisabled) {
  testing::internal::CaptureStderr();
  {
    Progress progress("moisture", false);
    progress.update(0.5);
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

TEST(Progress, PrintsPercentAndFinishesTheLine) {
  testing::internal::CaptureStderr();
  {
    Progress progress("sunniness", true);
    progress.update(0.42);
    progress.update(0.43);  // within 100 ms: not printed again
  }
  std::string text = testing::internal::GetCapturedStderr();
  EXPECT_NE(text.find("sunniness"), std::string::npos);
  EXPECT_NE(text.find(" 42%"), std::string::npos);
  EXPECT_EQ(text.find(" 43%"), std::string::npos);
  EXPECT_EQ(text.back(), '\n');
}

}  // namespace eco

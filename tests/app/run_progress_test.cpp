#include "app/run_progress.hpp"

#include <gtest/gtest.h>

namespace eco {
namespace {

TEST(RunProgress, PlainLinesAboutEveryTenthOfTheRun) {
  testing::internal::CaptureStderr();
  for (int year = 1; year <= 40; ++year)
    showRunProgress({year, 40, 1, static_cast<std::size_t>(100 * year), 0.5 * year}, false);
  const std::string lines = testing::internal::GetCapturedStderr();
  // Every fourth year of forty, at two years a second: the rest takes (40 - year) / 2 s.
  EXPECT_EQ(std::count(lines.begin(), lines.end(), '\n'), 10);
  EXPECT_NE(lines.find("year 4/40: 400 plants, 2.0 years/s, ETA 0:18\n"), std::string::npos)
      << lines;
  EXPECT_NE(lines.find("year 40/40: 4000 plants, 2.0 years/s, ETA 0:00\n"), std::string::npos);
}

TEST(RunProgress, SlowYearsShowSecondsAYear) {
  // A landscape's years take half a minute each: 5 years in 130 s is 26 s a year, and the
  // 45 years left take 1,170 s.
  testing::internal::CaptureStderr();
  showRunProgress({55, 100, 51, 1000, 130.0}, false);
  showRunProgress({55, 100, 51, 1000, 130.0}, true);
  const std::string text = testing::internal::GetCapturedStderr();
  EXPECT_NE(text.find("year 55/100: 1000 plants, 26.0 s/year, ETA 19:30\n"), std::string::npos)
      << text;
  EXPECT_NE(text.find("1000 plants  26.0 s/year  ETA 19:30"), std::string::npos) << text;
}

TEST(RunProgress, ABarRedrawnInPlaceOnATerminal) {
  testing::internal::CaptureStderr();
  showRunProgress({20, 40, 1, 123, 10.0}, true);
  const std::string bar = testing::internal::GetCapturedStderr();
  EXPECT_EQ(bar.front(), '\r');
  EXPECT_NE(bar.find("year 20/40 [############............] 123 plants"), std::string::npos) << bar;
  EXPECT_EQ(bar.find('\n'), std::string::npos);  // only the last year ends the line
}

TEST(RunProgress, TheUserSeesProgressAndWarningsOnStderr) {
  RunOptions options;
  reportToTheUser(options);
  ASSERT_TRUE(options.progress && options.warn);
  testing::internal::CaptureStderr();
  options.warn("nothing will grow");
  options.progress({1, 1, 1, 5, 1.0});
  const std::string text = testing::internal::GetCapturedStderr();
  EXPECT_NE(text.find("ecoforest: warning: nothing will grow\n"), std::string::npos) << text;
  EXPECT_NE(text.find("year 1/1"), std::string::npos) << text;
}

}  // namespace
}  // namespace eco

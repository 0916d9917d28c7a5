#include "core/csv_text.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace eco {
namespace {

TEST(CsvText, LinesComeWithTheirNumbers) {
  std::vector<std::pair<int, std::string>> lines;
  forEachLine("a,b\n\nc\nlast",
              [&](int n, std::string_view line) { lines.emplace_back(n, std::string(line)); });
  EXPECT_EQ(lines,
            (std::vector<std::pair<int, std::string>>{{1, "a,b"}, {2, ""}, {3, "c"}, {4, "last"}}));
  int calls = 0;
  forEachLine("", [&](int, std::string_view) { ++calls; });
  EXPECT_EQ(calls, 0);
}

TEST(CsvText, FieldsAreSplitAtCommasAndASurplusIsCounted) {
  std::string_view fields[3];
  EXPECT_EQ(splitFields("1,x,", fields), 3u);
  EXPECT_EQ(fields[0], "1");
  EXPECT_EQ(fields[1], "x");
  EXPECT_EQ(fields[2], "");
  EXPECT_EQ(splitFields("7", fields), 1u);
  EXPECT_EQ(fields[0], "7");
  EXPECT_EQ(splitFields("a,b,c,d,e", fields), 4u);  // more than there is room for
}

TEST(CsvText, NumbersAreParsedWhole) {
  double d = 0.0;
  EXPECT_TRUE(parseField("12.5", d));
  EXPECT_DOUBLE_EQ(d, 12.5);
  EXPECT_FALSE(parseField("12.5m", d));
  EXPECT_FALSE(parseField("", d));
  int i = 0;
  EXPECT_FALSE(parseField("3.5", i));
  EXPECT_TRUE(parseField("-4", i));
  EXPECT_EQ(i, -4);
}

TEST(CsvText, NonFiniteNumbersAreRefused) {
  double d = 0.0;
  float f = 0.0f;
  for (const char* field : {"nan", "NaN", "inf", "-inf", "infinity", "1e999"}) {
    EXPECT_FALSE(parseField(field, d)) << field;
    EXPECT_FALSE(parseField(field, f)) << field;
  }
  EXPECT_FALSE(parseField("1e39", f));  // beyond a float
}

// printf's "%.*f" is the oracle: the exact decimal value of the float, rounded half to even.
std::string printed(float value, int decimals) {
  char text[128];
  std::snprintf(text, sizeof text, "%.*f", decimals, static_cast<double>(value));
  return text;
}

TEST(CsvText, FixedDecimalsAreRoundedAsPrintfRoundsThem) {
  auto fixed = [](float value, int decimals) {
    std::string out = "x";
    appendFixed(out, value, decimals);
    return out.substr(1);  // appended, not replaced
  };
  EXPECT_EQ(fixed(12.3456f, 3), "12.346");
  EXPECT_EQ(fixed(0.0625f, 3), "0.062");  // exactly halfway: to the even digit
  EXPECT_EQ(fixed(0.1875f, 3), "0.188");
  EXPECT_EQ(fixed(-0.0001f, 2), "-0.00");  // the sign stays, as printf keeps it
  EXPECT_EQ(fixed(-0.0f, 2), "-0.00");
  EXPECT_EQ(fixed(7.0f, 0), "7");
  EXPECT_EQ(fixed(std::numeric_limits<float>::max(), 20),
            printed(std::numeric_limits<float>::max(), 20));
  std::mt19937 random(7);
  std::uniform_real_distribution<float> coordinate(-5.0e4f, 5.0e4f);
  for (int i = 0; i < 20000; ++i) {
    const float value = i % 2 ? coordinate(random) : coordinate(random) * 1e-4f;
    for (int decimals = 0; decimals <= 4; ++decimals)
      ASSERT_EQ(fixed(value, decimals), printed(value, decimals)) << value << " " << decimals;
  }
  // Every magnitude a float has and every count of decimals, on both sides of where the
  // scaled integer stops fitting 64 bits (1e18) and of the 12 decimals scaled exactly.
  std::uniform_real_distribution<float> mantissa(-1.0f, 1.0f);
  std::uniform_int_distribution<int> exponent(-40, 127);
  for (int i = 0; i < 20000; ++i) {
    const float value = std::ldexp(mantissa(random), exponent(random));
    for (int decimals = 0; decimals <= 20; ++decimals)
      ASSERT_EQ(fixed(value, decimals), printed(value, decimals)) << value << " " << decimals;
  }
  for (const float edge : {1e6f, 999999.94f, 1e5f, 123456.7f, 0.5f, 1.5f, 2.5f, -2.5f})
    for (int decimals = 0; decimals <= 20; ++decimals)
      EXPECT_EQ(fixed(edge, decimals), printed(edge, decimals)) << edge << " " << decimals;
}

TEST(CsvText, IntegersAreWrittenAsPrintfWritesThem) {
  auto integer = [](auto value) {
    std::string out = "x";
    appendInteger(out, value);
    return out.substr(1);  // appended, not replaced
  };
  auto printedInteger = [](long long value) {
    char text[32];
    std::snprintf(text, sizeof text, "%lld", value);
    return std::string(text);
  };
  EXPECT_EQ(integer(0), "0");
  EXPECT_EQ(integer(-17), "-17");
  EXPECT_EQ(integer(std::numeric_limits<std::int64_t>::min()), "-9223372036854775808");
  EXPECT_EQ(integer(std::numeric_limits<std::uint64_t>::max()), "18446744073709551615");
  EXPECT_EQ(integer(std::numeric_limits<std::uint32_t>::max()), "4294967295");
  std::mt19937_64 random(11);
  for (int i = 0; i < 1000; ++i) {
    const auto value = static_cast<std::int64_t>(random()) >> (i % 60);
    ASSERT_EQ(integer(value), printedInteger(value));
    ASSERT_EQ(integer(static_cast<std::int32_t>(value)),
              printedInteger(static_cast<std::int32_t>(value)));
  }
}

}  // namespace
}  // namespace eco

#include "core/memory.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace eco {
namespace {

TEST(Memory, TheSystemSaysWhatIsAvailable) {
  const auto available = availableMemoryBytes();
  ASSERT_TRUE(available.has_value());  // Linux has MemAvailable since 3.14
  EXPECT_GT(*available, 0u);
}

TEST(Memory, MoreThanThereIsIsRefusedUnlessIgnored) {
  const std::uint64_t tooMuch = *availableMemoryBytes() * 4;
  try {
    requireMemory(tooMuch, "this terrain", "--ignore-memory-check", false);
    FAIL() << "no refusal";
  } catch (const EnvironmentError& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("this terrain needs about " + formatBytes(tooMuch)), std::string::npos);
    EXPECT_NE(text.find("--ignore-memory-check"), std::string::npos) << text;
  }
  EXPECT_NO_THROW(requireMemory(tooMuch, "this terrain", "--ignore-memory-check", true));
  EXPECT_NO_THROW(requireMemory(1000, "a little", "", false));
}

TEST(Memory, BytesReadAsAPersonWritesThem) {
  EXPECT_EQ(formatBytes(4'500'000'000ull), "4.5 GB");
  EXPECT_EQ(formatBytes(18'000'000'000ull), "18 GB");
  EXPECT_EQ(formatBytes(250'000'000ull), "250.0 MB");
}

}  // namespace
}  // namespace eco

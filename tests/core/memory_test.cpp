#include "core/memory.hpp"

#include <gtest/gtest.h>

#include <vector>

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
    requireMemory(tooMuch, "this terrain", "Use --ignore-memory-check to go ahead.", false);
    FAIL() << "no refusal";
  } catch (const EnvironmentError& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("this terrain needs about " + formatBytes(tooMuch) + " of memory; "),
              std::string::npos)
        << text;
    EXPECT_TRUE(text.ends_with("is available. Use --ignore-memory-check to go ahead.")) << text;
  }
  EXPECT_NO_THROW(requireMemory(tooMuch, "this terrain", "", true));
  EXPECT_NO_THROW(requireMemory(1000, "a little", "", false));
}

TEST(Memory, AShrunkArrayGivesBackThePagesPastItsElements) {
  // 200 MB written (resident), shrunk to 20 MB: its storage keeps the pages until released.
  std::vector<std::uint32_t> array(50'000'000);
  for (std::size_t i = 0; i < array.size(); ++i) array[i] = static_cast<std::uint32_t>(i);
  array.resize(5'000'000);
  const std::size_t capacity = array.capacity();
  const std::optional<std::uint64_t> before = residentMemoryBytes();
  releaseUnusedCapacity(array);
  const std::optional<std::uint64_t> after = residentMemoryBytes();
  ASSERT_TRUE(before && after);  // Linux has VmRSS
  EXPECT_GT(*before, *after + 170'000'000) << *before << " before, " << *after << " after";
  // The elements and the capacity stay; grown again, the new elements are what resize writes.
  EXPECT_EQ(array.capacity(), capacity);
  for (std::size_t i = 0; i < array.size(); i += 4999) ASSERT_EQ(array[i], i);
  array.resize(50'000'000, 7u);
  EXPECT_EQ(array[5'000'000], 7u);
  EXPECT_EQ(array.back(), 7u);
}

TEST(Memory, BytesReadAsAPersonWritesThem) {
  EXPECT_EQ(formatBytes(4'500'000'000ull), "4.5 GB");
  EXPECT_EQ(formatBytes(18'000'000'000ull), "18 GB");
  EXPECT_EQ(formatBytes(250'000'000ull), "250.0 MB");
}

}  // namespace
}  // namespace eco

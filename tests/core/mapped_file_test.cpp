#include "core/mapped_file.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "test_files.hpp"

namespace eco {
namespace {

TEST(MappedFile, HoldsTheFilesBytes) {
  const auto folder = test::freshDirectory("mapped_file");
  std::string bytes(3 * 4096 + 17, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 7);
  test::writeFile(folder / "some.bin", bytes);
  const std::optional<MappedFile> mapped = MappedFile::open(folder / "some.bin");
  ASSERT_TRUE(mapped.has_value());
  EXPECT_EQ(mapped->bytes(), bytes);
  // Moved, the mapping stays valid and is unmapped once.
  const MappedFile moved(std::move(*MappedFile::open(folder / "some.bin")));
  EXPECT_EQ(moved.bytes(), bytes);
}

// The resident memory of the process's mappings of `file` (Linux's /proc/self/smaps).
std::size_t residentKiBOf(const std::filesystem::path& file) {
  std::ifstream smaps("/proc/self/smaps");
  std::size_t kib = 0;
  bool ours = false;
  for (std::string line; std::getline(smaps, line);) {
    if (line.find('-') < line.find(' ') && line.find(' ') != std::string::npos)
      ours =
          line.size() >= file.string().size() &&
          line.compare(line.size() - file.string().size(), std::string::npos, file.string()) == 0;
    else if (ours && line.rfind("Rss:", 0) == 0)
      kib += std::stoul(line.substr(4));
  }
  return kib;
}

// Read in parts, a part released leaves the process's memory, and reads the same again.
TEST(MappedFile, APartReleasedLeavesTheMemoryAndReadsTheSameAgain) {
  const auto file = test::freshDirectory("mapped_file_parts") / "parts.bin";
  std::string bytes(std::size_t{8} << 20, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 13 + i / 4096);
  test::writeFile(file, bytes);
  const std::optional<MappedFile> mapped = MappedFile::open(file, MappedFile::Reading::InParts);
  ASSERT_TRUE(mapped.has_value());
  EXPECT_EQ(mapped->bytes(), bytes);  // every page read
  EXPECT_GE(residentKiBOf(file), std::size_t{7} << 10);
  // The whole pages inside a part go; a page it shares with the next part stays.
  mapped->release(mapped->bytes().substr(0, (std::size_t{6} << 20) + 100));
  EXPECT_LE(residentKiBOf(file), std::size_t{3} << 10);
  EXPECT_EQ(mapped->bytes(), bytes);
  mapped->release(mapped->bytes());
  mapped->release(mapped->bytes().substr(5, 0));  // nothing
  EXPECT_LE(residentKiBOf(file), std::size_t{1} << 10);
  EXPECT_EQ(mapped->bytes(), bytes);
}

TEST(MappedFile, AnEmptyFileIsEmptyAndAMissingFileOrAFolderIsNothing) {
  const auto folder = test::freshDirectory("mapped_file_edges");
  test::writeFile(folder / "empty", "");
  const std::optional<MappedFile> empty = MappedFile::open(folder / "empty");
  ASSERT_TRUE(empty.has_value());
  EXPECT_TRUE(empty->bytes().empty());
  EXPECT_FALSE(MappedFile::open(folder / "missing").has_value());
  EXPECT_FALSE(MappedFile::open(folder).has_value());
}

}  // namespace
}  // namespace eco

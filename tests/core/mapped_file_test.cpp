#include "core/mapped_file.hpp"

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

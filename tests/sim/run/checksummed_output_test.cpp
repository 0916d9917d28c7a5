#include "sim/run/checksummed_output.hpp"

#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "core/hash.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

std::string patternOf(std::size_t size) {
  std::string bytes(size, '\0');
  for (std::size_t i = 0; i < size; ++i) bytes[i] = static_cast<char>((i * 131 + i / 977) & 0xff);
  return bytes;
}

TEST(ChecksummedOutput, ASmallBodyIsTheHashOfItsOneBlocksHash) {
  const std::string bytes = "a few bytes";
  const std::uint64_t block = fnv1a64(bytes);
  EXPECT_EQ(blockChecksum(bytes),
            fnv1a64(std::string_view(reinterpret_cast<const char*>(&block), sizeof block)));
}

// Pieces of any size, meeting the 1 MiB blocks anywhere, give the file the bytes and the
// checksum of the whole.
TEST(ChecksummedOutput, PiecesOfAnySizeGiveTheChecksumOfTheWhole) {
  const std::string whole = patternOf((std::size_t{3} << 20) + 12345);
  const auto file = test::freshDirectory("checksummed_output") / "pieces.bin";
  std::uint64_t checksum = 0;
  {
    AtomicFile out(file);
    ChecksummedOutput body(out);
    std::size_t at = 0;
    for (std::size_t piece : {std::size_t{7}, std::size_t{1} << 20, std::size_t{1000},
                              std::size_t{2} << 20, whole.size()}) {
      piece = std::min(piece, whole.size() - at);
      body.add(std::string_view(whole).substr(at, piece));
      at += piece;
    }
    checksum = body.finish();
    out.commit();
  }
  EXPECT_EQ(test::readFile(file), whole);
  EXPECT_EQ(checksum, blockChecksum(whole));
}

TEST(ChecksummedOutput, ABodyIsCheckedAgainstTheChecksumAfterIt) {
  const std::string body = patternOf(5000);
  const std::uint64_t checksum = blockChecksum(body);
  std::string sealed = body + std::string(reinterpret_cast<const char*>(&checksum), 8);
  ASSERT_TRUE(checkedBody(sealed).has_value());
  EXPECT_EQ(*checkedBody(sealed), body);
  sealed[100] ^= 1;
  EXPECT_FALSE(checkedBody(sealed).has_value());
  EXPECT_FALSE(checkedBody(sealed.substr(0, sealed.size() - 1)).has_value());
  EXPECT_FALSE(checkedBody("1234567").has_value());
}

}  // namespace
}  // namespace eco

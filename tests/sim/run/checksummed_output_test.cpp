#include "sim/run/checksummed_output.hpp"

#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
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

// Pieces of any size, meeting the 1 MiB blocks anywhere, give the file the bytes of the
// whole followed by their checksum.
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
  EXPECT_EQ(checksum, blockChecksum(whole));
  EXPECT_EQ(test::readFile(file),
            whole + std::string(reinterpret_cast<const char*>(&checksum), sizeof checksum));
}

// The bytes are hashed in parts of 64 MiB, each handed on once hashed, in order: the
// checksum of the blocks is the same, in parts or not.
TEST(ChecksummedOutput, TheHashedPartsAreHandedOnInOrder) {
  const std::string whole = patternOf((std::size_t{130} << 20) + 777);
  std::vector<std::string_view> parts;
  const std::uint64_t inParts =
      blockChecksum(whole, [&](std::string_view part) { parts.push_back(part); });
  EXPECT_EQ(inParts, blockChecksum(whole));
  ASSERT_EQ(parts.size(), 3u);
  std::size_t at = 0;
  for (const std::string_view part : parts) {
    EXPECT_EQ(part.data(), whole.data() + at);
    at += part.size();
  }
  EXPECT_EQ(at, whole.size());
  EXPECT_EQ(parts[0].size(), std::size_t{64} << 20);
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

// The bytes of a file written as the magic "MAGIC", version 3 and `body`.
std::string sealedFileOf(std::string_view body) {
  const auto file = test::freshDirectory("checksummed_sealed") / "sealed.bin";
  AtomicFile out(file);
  ChecksummedOutput output(out);
  output.add(sealedHeader("MAGIC", 3).bytes());
  output.add(body);
  output.finish();
  out.commit();
  return test::readFile(file);
}

// A file written as its magic, version and body opens to the body; another magic, another
// version or a changed byte does not.
TEST(ChecksummedOutput, ASealedFileOpensToItsBodyAfterTheHeader) {
  const std::string bytes = sealedFileOf("the body");
  const SealedFile sealed = openSealed(bytes, "MAGIC", 3);
  EXPECT_EQ(sealed.fault, SealedFile::Fault::None);
  EXPECT_EQ(sealed.afterHeader, "the body");
  EXPECT_EQ(openSealed(bytes, "OTHER", 3).fault, SealedFile::Fault::NotOurs);
  EXPECT_EQ(openSealed("", "MAGIC", 3).fault, SealedFile::Fault::NotOurs);
  EXPECT_EQ(openSealed(bytes, "MAGIC", 4).fault, SealedFile::Fault::OtherVersion);
  std::string changed = bytes;
  changed[changed.size() - 10] ^= 1;
  EXPECT_EQ(openSealed(changed, "MAGIC", 3).fault, SealedFile::Fault::Corrupt);
}

// requireSealed gives the body, or an InputError at the file with the reader's words for the
// check that failed.
TEST(ChecksummedOutput, ASealedFileThatFailsACheckIsRefusedInTheReadersWords) {
  const std::string bytes = sealedFileOf("the body");
  const SealedFileFaults say{.notOurs = "not ours", .otherVersion = "other", .corrupt = "broken"};
  EXPECT_EQ(requireSealed(bytes, "MAGIC", 3, "f.bin", say), "the body");
  auto refusal = [&](std::string_view file, std::string_view magic, std::uint32_t version) {
    try {
      requireSealed(file, magic, version, "f.bin", say);
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().file, "f.bin");
      return e.message();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal(bytes, "OTHER", 3), "not ours");
  EXPECT_EQ(refusal(bytes, "MAGIC", 4), "other");
  std::string changed = bytes;
  changed[changed.size() - 10] ^= 1;
  EXPECT_EQ(refusal(changed, "MAGIC", 3), "broken");
}

}  // namespace
}  // namespace eco

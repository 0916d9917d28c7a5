#include "sim/run/checksummed_output.hpp"

#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <xxhash.h>

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
  const std::uint64_t xxh3 = XXH3_64bits(bytes.data(), bytes.size());
  EXPECT_EQ(blockChecksum(bytes, BlockHash::Xxh3), XXH3_64bits(&xxh3, sizeof xxh3));
  const std::uint64_t fnv = fnv1a64(bytes);
  EXPECT_EQ(blockChecksum(bytes, BlockHash::Fnv1a),
            fnv1a64(std::string_view(reinterpret_cast<const char*>(&fnv), sizeof fnv)));
}

// Blocks of 1 MiB: a body of two and a bit is the hash of its three blocks' hashes.
TEST(ChecksummedOutput, ALongBodyIsTheHashOfItsBlocksHashes) {
  const std::string bytes = patternOf((std::size_t{2} << 20) + 5);
  std::uint64_t blocks[3];
  for (std::size_t b = 0; b < 3; ++b) {
    const std::string_view block = std::string_view(bytes).substr(b << 20, std::size_t{1} << 20);
    blocks[b] = XXH3_64bits(block.data(), block.size());
  }
  EXPECT_EQ(blockChecksum(bytes, BlockHash::Xxh3), XXH3_64bits(blocks, sizeof blocks));
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
  EXPECT_EQ(checksum, blockChecksum(whole, BlockHash::Xxh3));
  EXPECT_EQ(test::readFile(file),
            whole + std::string(reinterpret_cast<const char*>(&checksum), sizeof checksum));
}

// The bytes are hashed in parts of 64 MiB, each handed on once hashed, in order: the
// checksum of the blocks is the same, in parts or not.
TEST(ChecksummedOutput, TheHashedPartsAreHandedOnInOrder) {
  const std::string whole = patternOf((std::size_t{130} << 20) + 777);
  std::vector<std::string_view> parts;
  const std::uint64_t inParts =
      blockChecksum(whole, BlockHash::Xxh3, [&](std::string_view part) { parts.push_back(part); });
  EXPECT_EQ(inParts, blockChecksum(whole, BlockHash::Xxh3));
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
  const std::uint64_t checksum = blockChecksum(body, BlockHash::Xxh3);
  std::string sealed = body + std::string(reinterpret_cast<const char*>(&checksum), 8);
  ASSERT_TRUE(checkedBody(sealed, BlockHash::Xxh3).has_value());
  EXPECT_EQ(*checkedBody(sealed, BlockHash::Xxh3), body);
  EXPECT_FALSE(checkedBody(sealed, BlockHash::Fnv1a).has_value());  // another hash's checksum
  sealed[100] ^= 1;
  EXPECT_FALSE(checkedBody(sealed, BlockHash::Xxh3).has_value());
  EXPECT_FALSE(checkedBody(sealed.substr(0, sealed.size() - 1), BlockHash::Xxh3).has_value());
  EXPECT_FALSE(checkedBody("1234567", BlockHash::Xxh3).has_value());
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

constexpr SealedVersion kVersion3[] = {{3, BlockHash::Xxh3}};
constexpr SealedVersion kVersion4[] = {{4, BlockHash::Xxh3}};

// A file written as its magic, version and body opens to the body; another magic, another
// version or a changed byte does not.
TEST(ChecksummedOutput, ASealedFileOpensToItsBodyAfterTheHeader) {
  const std::string bytes = sealedFileOf("the body");
  const SealedFile sealed = openSealed(bytes, "MAGIC", kVersion3);
  EXPECT_EQ(sealed.fault, SealedFile::Fault::None);
  EXPECT_EQ(sealed.afterHeader, "the body");
  EXPECT_EQ(openSealed(bytes, "OTHER", kVersion3).fault, SealedFile::Fault::NotOurs);
  EXPECT_EQ(openSealed("", "MAGIC", kVersion3).fault, SealedFile::Fault::NotOurs);
  EXPECT_EQ(openSealed(bytes, "MAGIC", kVersion4).fault, SealedFile::Fault::OtherVersion);
  std::string changed = bytes;
  changed[changed.size() - 10] ^= 1;
  EXPECT_EQ(openSealed(changed, "MAGIC", kVersion3).fault, SealedFile::Fault::Corrupt);
}

// An older version a reader still reads is checked by its own hash: a file of version 2
// sealed by FNV-1a opens where version 2 is read as FNV-1a, and is corrupt where its
// version is taken for one checksummed by XXH3.
TEST(ChecksummedOutput, AnOlderVersionIsCheckedByTheHashItWasSealedWith) {
  const std::string header = sealedHeader("MAGIC", 2).bytes();
  const std::string body = header + "the body";
  const std::uint64_t fnv = blockChecksum(body, BlockHash::Fnv1a);
  const std::string bytes = body + std::string(reinterpret_cast<const char*>(&fnv), 8);
  constexpr SealedVersion kBoth[] = {{3, BlockHash::Xxh3}, {2, BlockHash::Fnv1a}};
  const SealedFile sealed = openSealed(bytes, "MAGIC", kBoth);
  EXPECT_EQ(sealed.fault, SealedFile::Fault::None);
  EXPECT_EQ(sealed.afterHeader, "the body");
  constexpr SealedVersion kTwoByXxh3[] = {{2, BlockHash::Xxh3}};
  EXPECT_EQ(openSealed(bytes, "MAGIC", kTwoByXxh3).fault, SealedFile::Fault::Corrupt);
  EXPECT_EQ(openSealed(bytes, "MAGIC", kVersion3).fault, SealedFile::Fault::OtherVersion);
}

// requireSealed gives the body, or an InputError at the file with the reader's words for the
// check that failed.
TEST(ChecksummedOutput, ASealedFileThatFailsACheckIsRefusedInTheReadersWords) {
  const std::string bytes = sealedFileOf("the body");
  const SealedFileFaults say{.notOurs = "not ours", .otherVersion = "other", .corrupt = "broken"};
  EXPECT_EQ(requireSealed(bytes, "MAGIC", kVersion3, "f.bin", say), "the body");
  auto refusal = [&](std::string_view file, std::string_view magic,
                     std::span<const SealedVersion> readable) {
    try {
      requireSealed(file, magic, readable, "f.bin", say);
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().file, "f.bin");
      return e.message();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal(bytes, "OTHER", kVersion3), "not ours");
  EXPECT_EQ(refusal(bytes, "MAGIC", kVersion4), "other");
  std::string changed = bytes;
  changed[changed.size() - 10] ^= 1;
  EXPECT_EQ(refusal(changed, "MAGIC", kVersion3), "broken");
}

}  // namespace
}  // namespace eco

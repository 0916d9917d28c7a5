// ecoforest's binary files (checkpoint.bin, binary tree snapshots): a magic, a format
// version, the body, then the checksum of everything before it by the hash of that version.
// A writer makes the checksum while the bytes go through to their file (a landscape's file
// is gigabytes, which would otherwise be held in memory to be hashed); a reader checks the
// three before the body.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/binary_io.hpp"

namespace eco {

// Told of each part of a file's bytes once it has been gone through, in order: a reader of
// a file mapped in parts releases it (MappedFile::release).
using PartDone = std::function<void(std::string_view)>;

// The hash of a file's blocks and of their hashes: FNV-1a in the formats ecoforest first
// wrote, XXH3 (xxHash) in those since, which a checksum of a landscape's gigabytes waited on:
// FNV-1a goes a byte at a time through a multiplication (0.7 GB/s a core here), XXH3 reads a
// vector at a time (4.4 GB/s, this machine's memory's pace).
enum class BlockHash { Fnv1a, Xxh3 };
// The hash ChecksummedOutput seals files with: each format's current version's.
inline constexpr BlockHash kWrittenHash = BlockHash::Xxh3;

// The hash of each 1 MiB block (in parallel), then the hash of the blocks' hashes; the bytes
// hashed 64 MiB at a time, each part handed to `hashed` when it is.
std::uint64_t blockChecksum(std::string_view bytes, BlockHash hash, const PartDone& hashed = {});

// A file's first bytes: its magic and format version, for the writer to add more to.
BinaryWriter sealedHeader(std::string_view magic, std::uint32_t version);

// Writes bytes through to `out` as they come, hashing whole blocks on the way; finish()
// writes the rest and after it their blockChecksum() by kWrittenHash, which it returns.
class ChecksummedOutput {
 public:
  explicit ChecksummedOutput(AtomicFile& out) : out_(out) {}
  // Whole blocks go out; the rest waits for the next bytes.
  void add(std::string_view bytes);
  // A column as BinaryWriter::putVector lays it out, straight from the vector.
  template <typename T>
  void addVector(const std::vector<T>& values) {
    const std::uint64_t count = values.size();
    add(std::string_view(reinterpret_cast<const char*>(&count), sizeof count));
    add(std::string_view(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)));
  }
  std::uint64_t finish();

 private:
  void emit(std::string_view bytes);
  AtomicFile& out_;
  std::string pending_;
  std::vector<std::uint64_t> hashes_;
};

// Splits a file's bytes into the body and the checksum stored after it; nothing when the
// file is too short to hold one or the stored checksum is not the body's.
std::optional<std::string_view> checkedBody(std::string_view bytes, BlockHash hash,
                                            const PartDone& hashed = {});

// A format version a reader reads, and the hash its files' checksums are made with: a
// reader reads its current version and older ones of the same layout.
struct SealedVersion {
  std::uint32_t number = 0;
  BlockHash hash = kWrittenHash;
};

// A file's bytes after its magic and version, checked in that order.
struct SealedFile {
  enum class Fault { None, NotOurs, OtherVersion, Corrupt };
  Fault fault = Fault::None;
  std::string_view afterHeader;  // the body past the magic and version, without the checksum
};
SealedFile openSealed(std::string_view bytes, std::string_view magic,
                      std::span<const SealedVersion> readable, const PartDone& hashed = {});

// What a reader says, in its own words, when its file fails each of openSealed's checks.
struct SealedFileFaults {
  std::string notOurs, otherVersion, corrupt;
};
// openSealed's body past the header, or an InputError naming `file` with the words of the
// check that failed.
std::string_view requireSealed(std::string_view bytes, std::string_view magic,
                               std::span<const SealedVersion> readable,
                               const std::filesystem::path& file, const SealedFileFaults& say,
                               const PartDone& hashed = {});

}  // namespace eco

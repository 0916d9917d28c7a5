#include "sim/run/checksummed_output.hpp"

#include <algorithm>
#include <cstring>

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <xxhash.h>

#include "core/error.hpp"
#include "core/hash.hpp"

namespace eco {
namespace {

constexpr std::size_t kChecksumBlock = std::size_t{1} << 20;

std::uint64_t hashOf(std::string_view bytes, BlockHash hash) {
  return hash == BlockHash::Xxh3 ? XXH3_64bits(bytes.data(), bytes.size()) : fnv1a64(bytes);
}

// The hash of each block of `bytes`, in parallel, appended to `hashes`.
void appendBlockHashes(std::string_view bytes, BlockHash hash, std::vector<std::uint64_t>& hashes) {
  const std::size_t first = hashes.size();
  const std::size_t blocks = (bytes.size() + kChecksumBlock - 1) / kChecksumBlock;
  hashes.resize(first + blocks);
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    hashes[first + b] = hashOf(bytes.substr(b * kChecksumBlock, kChecksumBlock), hash);
  });
}

std::uint64_t combineBlockHashes(const std::vector<std::uint64_t>& hashes, BlockHash hash) {
  return hashOf(std::string_view(reinterpret_cast<const char*>(hashes.data()),
                                 hashes.size() * sizeof(std::uint64_t)),
                hash);
}

}  // namespace

std::uint64_t blockChecksum(std::string_view bytes, BlockHash hash, const PartDone& hashed) {
  constexpr std::size_t kPart = 64 * kChecksumBlock;  // whole blocks: the same blocks' hashes
  std::vector<std::uint64_t> hashes;
  for (std::size_t at = 0; at < bytes.size(); at += kPart) {
    const std::string_view part = bytes.substr(at, kPart);
    appendBlockHashes(part, hash, hashes);
    if (hashed) hashed(part);
  }
  return combineBlockHashes(hashes, hash);
}

void ChecksummedOutput::add(std::string_view bytes) {
  if (!pending_.empty()) {
    const std::size_t take = std::min(kChecksumBlock - pending_.size(), bytes.size());
    pending_.append(bytes.substr(0, take));
    bytes.remove_prefix(take);
    if (pending_.size() < kChecksumBlock) return;
    emit(pending_);
    pending_.clear();
  }
  const std::size_t whole = bytes.size() - bytes.size() % kChecksumBlock;
  emit(bytes.substr(0, whole));
  pending_.assign(bytes.substr(whole));
}

BinaryWriter sealedHeader(std::string_view magic, std::uint32_t version) {
  BinaryWriter header;
  header.putString(magic);
  header.put(version);
  return header;
}

std::uint64_t ChecksummedOutput::finish() {
  emit(pending_);
  pending_.clear();
  const std::uint64_t checksum = combineBlockHashes(hashes_, kWrittenHash);
  out_.write(std::string_view(reinterpret_cast<const char*>(&checksum), sizeof checksum));
  return checksum;
}

void ChecksummedOutput::emit(std::string_view bytes) {
  // Hashed while they are written: the system call's copy into the page cache takes one
  // core, the hashing the others.
  tbb::parallel_invoke([&] { appendBlockHashes(bytes, kWrittenHash, hashes_); },
                       [&] { out_.write(bytes); });
}

std::optional<std::string_view> checkedBody(std::string_view bytes, BlockHash hash,
                                            const PartDone& hashed) {
  if (bytes.size() < sizeof(std::uint64_t)) return std::nullopt;
  const std::string_view body = bytes.substr(0, bytes.size() - sizeof(std::uint64_t));
  std::uint64_t stored = 0;
  std::memcpy(&stored, bytes.data() + body.size(), sizeof stored);
  if (stored != blockChecksum(body, hash, hashed)) return std::nullopt;
  return body;
}

SealedFile openSealed(std::string_view bytes, std::string_view magic,
                      std::span<const SealedVersion> readable, const PartDone& hashed) {
  BinaryReader header(bytes);
  if (header.getString() != magic || header.failed()) return {SealedFile::Fault::NotOurs, {}};
  const auto number = header.get<std::uint32_t>();
  const auto version = std::find_if(readable.begin(), readable.end(),
                                    [&](const SealedVersion& v) { return v.number == number; });
  if (header.failed() || version == readable.end()) return {SealedFile::Fault::OtherVersion, {}};
  const std::optional<std::string_view> body = checkedBody(bytes, version->hash, hashed);
  // A forged checksum over bytes shorter than the header is no body either.
  const std::size_t headerBytes = bytes.size() - header.remaining();
  if (!body || headerBytes > body->size()) return {SealedFile::Fault::Corrupt, {}};
  return {SealedFile::Fault::None, body->substr(headerBytes)};
}

std::string_view requireSealed(std::string_view bytes, std::string_view magic,
                               std::span<const SealedVersion> readable,
                               const std::filesystem::path& file, const SealedFileFaults& say,
                               const PartDone& hashed) {
  const SealedFile sealed = openSealed(bytes, magic, readable, hashed);
  const std::string* why = nullptr;
  switch (sealed.fault) {
    case SealedFile::Fault::NotOurs:
      why = &say.notOurs;
      break;
    case SealedFile::Fault::OtherVersion:
      why = &say.otherVersion;
      break;
    case SealedFile::Fault::Corrupt:
      why = &say.corrupt;
      break;
    case SealedFile::Fault::None:
      return sealed.afterHeader;
  }
  throw InputError({file.string(), 0, ""}, *why);
}

}  // namespace eco

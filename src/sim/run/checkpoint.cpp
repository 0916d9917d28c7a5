#include "sim/run/checkpoint.hpp"

#include <cstring>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "core/atomic_file.hpp"
#include "core/binary_io.hpp"
#include "core/error.hpp"

namespace eco {
namespace {

constexpr std::string_view kMagic = "ECOFOREST-CHECKPOINT";
// 2: block checksum; 3: growth factor, stand measures; 4: 32-bit variant seeds
constexpr std::uint32_t kFormatVersion = 4;
constexpr std::size_t kChecksumBlock = std::size_t{1} << 20;

// FNV-1a of each 1 MiB block (in parallel: a checkpoint is written every year and can be
// tens of megabytes), then FNV-1a over the blocks' hashes.
std::uint64_t checksumOf(std::string_view bytes) {
  const std::size_t blocks = (bytes.size() + kChecksumBlock - 1) / kChecksumBlock;
  std::vector<std::uint64_t> hashes(blocks);
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    hashes[b] = fnv1a64(bytes.substr(b * kChecksumBlock, kChecksumBlock));
  });
  return fnv1a64(std::string_view(reinterpret_cast<const char*>(hashes.data()),
                                  hashes.size() * sizeof(std::uint64_t)));
}

}  // namespace

void writeCheckpoint(const std::filesystem::path& file, const Checkpoint& checkpoint) {
  BinaryWriter w;
  w.putString(kMagic);
  w.put(kFormatVersion);
  w.put(checkpoint.scenarioHash);
  w.putString(checkpoint.programVersion);
  w.put<std::int32_t>(checkpoint.state.year);
  w.put(checkpoint.state.nextId);
  checkpoint.state.plants.forEachColumn([&](const auto& column) { w.putVector(column); });
  w.putVector(checkpoint.stats);
  const std::uint64_t checksum = checksumOf(w.bytes());
  w.put(checksum);
  AtomicFile out(file);
  out.write(w.bytes());
  out.commit();
}

Checkpoint readCheckpoint(const std::filesystem::path& file, std::uint64_t expectedHash) {
  auto refuse = [&](const std::string& why) -> InputError {
    return InputError({file.string(), 0, ""}, why);
  };
  const std::optional<std::string> read = readFileBytes(file);
  if (!read) throw refuse("cannot open the checkpoint (was the run started in this folder?)");
  const std::string& bytes = *read;
  BinaryReader header(bytes);
  if (header.getString() != kMagic || header.failed()) throw refuse("not an ecoforest checkpoint");
  if (header.get<std::uint32_t>() != kFormatVersion)
    throw refuse("checkpoint format from another version of ecoforest; start the run afresh");
  if (bytes.size() < sizeof(std::uint64_t)) throw refuse("checkpoint is truncated");
  const std::string_view body(bytes.data(), bytes.size() - sizeof(std::uint64_t));
  std::uint64_t stored = 0;
  std::memcpy(&stored, bytes.data() + body.size(), sizeof stored);
  if (stored != checksumOf(body)) throw refuse("checkpoint is corrupt (checksum mismatch)");

  BinaryReader r(body);
  r.getString();
  r.get<std::uint32_t>();
  Checkpoint checkpoint;
  checkpoint.scenarioHash = r.get<std::uint64_t>();
  checkpoint.programVersion = r.getString();
  checkpoint.state.year = r.get<std::int32_t>();
  checkpoint.state.nextId = r.get<std::uint64_t>();
  checkpoint.state.plants.forEachColumn([&](auto& column) { r.getVector(column); });
  r.getVector(checkpoint.stats);
  if (r.failed() || !r.atEnd()) throw refuse("checkpoint is corrupt (unexpected length)");
  const std::size_t n = checkpoint.state.plants.size();
  bool consistent = true;
  checkpoint.state.plants.forEachColumn(
      [&](const auto& column) { consistent &= column.size() == n; });
  if (!consistent) throw refuse("checkpoint is corrupt (columns of different lengths)");
  if (checkpoint.scenarioHash != expectedHash)
    throw refuse(fmt::format(
        "checkpoint belongs to another scenario (fingerprint {:016x}, this scenario {:016x}); "
        "resume with the scenario and species files that started the run, or start afresh",
        checkpoint.scenarioHash, expectedHash));
  return checkpoint;
}

}  // namespace eco

// checkpoint.bin (docs/run_folder.md): everything a run needs to continue exactly where it
// stopped — the ecosystem state and the statistics so far — fingerprinted with the hash of
// the scenario and species files and ended by the blockChecksum (checksummed_output.hpp) of
// the bytes before it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/atomic_file.hpp"
#include "sim/ecology/ecosystem.hpp"
#include "sim/grid.hpp"
#include "sim/run/run_outputs.hpp"

namespace eco {

struct Checkpoint {
  std::uint64_t scenarioHash = 0;
  std::string programVersion;
  EcosystemState state;
  std::vector<StatsRow> stats;
};

void writeCheckpoint(const std::filesystem::path& file, const Checkpoint& checkpoint);
// The same from the run's own state into `out`, which the caller commits (a run, in the
// background), written through as it is made: no copy of the plants and no checkpoint-sized
// buffer.
void writeCheckpoint(AtomicFile& out, std::uint64_t scenarioHash, std::string_view programVersion,
                     const EcosystemState& state, const std::vector<StatsRow>& stats);

// Throws InputError for a missing, truncated, corrupt or foreign file; `expectedHash` is the
// fingerprint of the scenario being resumed.
Checkpoint readCheckpoint(const std::filesystem::path& file, std::uint64_t expectedHash);

// What a checkpoint's values must fit: the scenario being resumed.
struct CheckpointLimits {
  const Grid& grid;
  std::size_t speciesCount = 0;
  int targetYears = 0;
};

// A checkpoint is untrusted input, however good its checksum: every value is checked
// before the run uses it (the year, each plant's id, species, position, cell, age and
// sizes, each statistics row). InputError naming the file, the plant and the value at fault.
void checkCheckpoint(const Checkpoint& checkpoint, const CheckpointLimits& limits,
                     const std::filesystem::path& file);

}  // namespace eco

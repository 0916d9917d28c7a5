// checkpoint.bin (docs/run_folder.md): everything a run needs to continue exactly where it
// stopped — the ecosystem state and the statistics so far — fingerprinted with the hash of
// the scenario and species files and protected by a checksum.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/ecology/ecosystem.hpp"
#include "sim/run/run_outputs.hpp"

namespace eco {

struct Checkpoint {
  std::uint64_t scenarioHash = 0;
  std::string programVersion;
  EcosystemState state;
  std::vector<StatsRow> stats;
};

void writeCheckpoint(const std::filesystem::path& file, const Checkpoint& checkpoint);

// Throws InputError for a missing, truncated, corrupt or foreign file; `expectedHash` is the
// fingerprint of the scenario being resumed.
Checkpoint readCheckpoint(const std::filesystem::path& file, std::uint64_t expectedHash);

}  // namespace eco

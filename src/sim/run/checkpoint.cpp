#include "sim/run/checkpoint.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <tbb/parallel_sort.h>

#include "core/atomic_file.hpp"
#include "core/binary_io.hpp"
#include "core/error.hpp"
#include "core/mapped_file.hpp"
#include "sim/run/checksummed_output.hpp"
#include "sim/run/first_fault.hpp"

namespace eco {
namespace {

constexpr std::string_view kMagic = "ECOFOREST-CHECKPOINT";
// 2: block checksum; 3: growth factor, stand measures; 4: 32-bit variant seeds;
// 5: plants' origin, the plan's stats; 6: no ground, cell and variant seed columns (derived)
// 7: ages, crown base, vigor, light and growth factor in 16 bits (Fixed16), poor years in 8
// 8: XXH3 checksum (version 7, the same layout checksummed by FNV-1a, is still read)
constexpr std::uint32_t kFormatVersion = 8;
constexpr SealedVersion kReadableVersions[] = {{kFormatVersion, kWrittenHash},
                                               {7, BlockHash::Fnv1a}};

bool finiteAtLeast(float value, float least) {
  return std::isfinite(value) && value >= least;
}

// What is wrong with plant i, or nothing.
std::optional<std::string> plantFault(const Plants& p, std::size_t i, int year,
                                      const CheckpointLimits& limits) {
  const Grid& g = limits.grid;
  if (p.species[i] >= limits.speciesCount)
    return fmt::format("species index {}, but the scenario has {} species", p.species[i],
                       limits.speciesCount);
  if (!std::isfinite(p.east_m[i]) || !std::isfinite(p.north_m[i]) ||
      g.cellAt(p.east_m[i], p.north_m[i]) < 0)
    return fmt::format("position ({}, {}) m is not on the terrain", p.east_m[i], p.north_m[i]);
  if (p.age_years[i] > year)
    return fmt::format("age {} is not between 0 and the checkpoint's year {}", p.age_years[i],
                       year);
  if (!finiteAtLeast(p.height_m[i], 0.0f) || !finiteAtLeast(p.crownRadius_m[i], 0.0f) ||
      !finiteAtLeast(p.dbh_m[i], 0.0f))
    return fmt::format("height {} m, crown radius {} m or dbh {} m is not a number of at least 0",
                       p.height_m[i], p.crownRadius_m[i], p.dbh_m[i]);
  // Crown base, vigor and light are within their range whatever their bits (Fixed16).
  if (!(p.growthFactor[i] > 0.0f))
    return fmt::format("growth factor {} is not a positive number",
                       static_cast<float>(p.growthFactor[i]));
  if (p.alive[i] > 1) return fmt::format("alive flag {} is neither 0 nor 1", p.alive[i]);
  if (p.origin[i] > static_cast<std::uint8_t>(PlantOrigin::PlantedRuledOut))
    return fmt::format("origin {} is none of 0 (seeded), 1 (planted) and 2 (planted, ruled out)",
                       p.origin[i]);
  return std::nullopt;
}

std::optional<std::string> statsFault(const StatsRow& row, int year, std::size_t speciesCount) {
  if (row.year < 1 || row.year > year)
    return fmt::format("year {} is not between 1 and the checkpoint's year {}", row.year, year);
  if (row.species < kAllSpecies || row.species >= static_cast<std::int64_t>(speciesCount))
    return fmt::format("species index {}, but the scenario has {} species", row.species,
                       speciesCount);
  if (row.alive < 0 || row.born < 0 || row.died < 0 || row.planted < 0 ||
      row.diedAfterPlanting < 0 || row.removed < 0)
    return std::string("a negative count of plants");
  for (double value : {row.meanHeight_m, row.stemsPerHa, row.basalArea_m2PerHa, row.qmd_cm,
                       row.dominantHeight_m, row.sdi, row.volume_m3PerHa, row.coverFraction,
                       row.densestHectareBasalArea_m2PerHa, row.removedVolume_m3PerHa})
    if (!(std::isfinite(value) && value >= 0.0))
      return fmt::format("a measure of {} is not a number of at least 0", value);
  return std::nullopt;
}

}  // namespace

void checkCheckpoint(const Checkpoint& checkpoint, const CheckpointLimits& limits,
                     const std::filesystem::path& file) {
  auto refuse = [&](const std::string& why) {
    return InputError({file.string(), 0, ""},
                      "checkpoint does not fit this scenario or is corrupt: " + why +
                          "; start the run afresh (without --resume)");
  };
  const EcosystemState& state = checkpoint.state;
  if (state.year < 0 || state.year > limits.targetYears)
    throw refuse(fmt::format("its year {} is not between 0 and the run's {} years", state.year,
                             limits.targetYears));
  const Plants& p = state.plants;
  const std::size_t i = firstFaulty(p.size(), [&](std::size_t row) {
    return plantFault(p, row, state.year, limits).has_value();
  });
  if (i < p.size()) {
    throw refuse(
        fmt::format("plant {} (id {}): {}", i + 1, p.id[i], *plantFault(p, i, state.year, limits)));
  }
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.id[i] == 0 || p.id[i] >= state.nextId)
      throw refuse(fmt::format("plant {} has id {}: ids run from 1 to below the next id {}", i + 1,
                               p.id[i], state.nextId));
  // The plants are in order of place, not of id: a sorted copy shows a repeated id.
  std::vector<std::uint64_t> ids = p.id;
  tbb::parallel_sort(ids.begin(), ids.end());
  const auto repeated = std::adjacent_find(ids.begin(), ids.end());
  if (repeated != ids.end()) {
    const std::uint64_t id = *repeated;
    const auto firstRow = std::find(p.id.begin(), p.id.end(), id);
    const auto secondRow = std::find(firstRow + 1, p.id.end(), id);
    throw refuse(fmt::format("plants {} and {} have the same id {}", firstRow - p.id.begin() + 1,
                             secondRow - p.id.begin() + 1, id));
  }
  for (std::size_t r = 0; r < checkpoint.stats.size(); ++r)
    if (auto fault = statsFault(checkpoint.stats[r], state.year, limits.speciesCount))
      throw refuse(fmt::format("statistics row {}: {}", r + 1, *fault));
}

void writeCheckpoint(AtomicFile& out, std::uint64_t scenarioHash, std::string_view programVersion,
                     const EcosystemState& state, const std::vector<StatsRow>& stats) {
  ChecksummedOutput body(out);
  BinaryWriter header = sealedHeader(kMagic, kFormatVersion);
  header.put(scenarioHash);
  header.putString(programVersion);
  header.put<std::int32_t>(state.year);
  header.put(state.nextId);
  body.add(header.bytes());
  // Straight from the columns: nothing of the plants is copied.
  state.plants.forEachColumn([&](const auto& column) { body.addVector(column); });
  body.addVector(stats);
  body.finish();
}

void writeCheckpoint(const std::filesystem::path& file, const Checkpoint& checkpoint) {
  AtomicFile out(file);
  writeCheckpoint(out, checkpoint.scenarioHash, checkpoint.programVersion, checkpoint.state,
                  checkpoint.stats);
  out.commit();
}

Checkpoint readCheckpoint(const std::filesystem::path& file, std::uint64_t expectedHash) {
  auto refuse = [&](const std::string& why) -> InputError {
    return InputError({file.string(), 0, ""}, why);
  };
  const std::optional<MappedFile> mapping = MappedFile::open(file);
  if (!mapping) throw refuse("cannot open the checkpoint (was the run started in this folder?)");
  const std::string_view body = requireSealed(
      mapping->bytes(), kMagic, kReadableVersions, file,
      {.notOurs = "not an ecoforest checkpoint",
       .otherVersion = "checkpoint format from another version of ecoforest; start the run afresh",
       .corrupt = "checkpoint is corrupt (checksum mismatch)"});

  BinaryReader r(body);
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

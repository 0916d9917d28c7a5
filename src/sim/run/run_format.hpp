// The files of a run folder (docs/run_folder.md), each writer beside its reader: the paths,
// run.json and stats.csv. The tree snapshots are trees_file.hpp's; maps and conditions.json
// are written by condition_maps.hpp (`ecoforest conditions` writes the same layout),
// checkpoint.bin by checkpoint.hpp.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/ecology/canopy_gaps.hpp"
#include "sim/ecology/ecosystem.hpp"
#include "sim/run/trees_file.hpp"

namespace eco {

// Where each file of a run folder lives.
struct RunPaths {
  std::filesystem::path dir;

  std::filesystem::path runJson() const { return dir / "run.json"; }
  std::filesystem::path stats() const { return dir / "stats.csv"; }
  std::filesystem::path checkpoint() const { return dir / "checkpoint.bin"; }
  std::filesystem::path treesFolder() const { return dir / "trees"; }
  // trees/year_NNNN.csv or .bin
  std::filesystem::path snapshot(int year, SnapshotFormat format) const;
  // The snapshot of `year` there is: the binary one where both are, the CSV path where
  // neither is.
  std::filesystem::path existingSnapshot(int year) const;
  std::filesystem::path removedFolder() const { return dir / "removed"; }
  std::filesystem::path removed(int year) const;  // removed/year_NNNN.csv: the year's thinning
  std::filesystem::path conditionsJson() const { return dir / "conditions.json"; }
  std::filesystem::path mapsFolder() const { return dir / "maps"; }
  std::filesystem::path map(const std::string& name) const;  // maps/NAME.exr, raw floats
  // The years of the snapshots there are (either format), ascending, each once.
  std::vector<int> snapshotYears() const;
  // The names of the maps there are (maps/*.exr), sorted.
  std::vector<std::string> mapNames() const;
};

// One line of stats.csv: a species in a year, or the whole stand (species kAllSpecies).
// Plain numbers without padding so that checkpoints can hold rows.
inline constexpr std::int32_t kAllSpecies = -1;
inline constexpr const char* kAllSpeciesName = "all";  // its name in the files
struct StatsRow {
  std::int32_t year = 0;
  std::int32_t species = 0;
  std::int64_t alive = 0, born = 0, died = 0;
  // The plan's doings (docs/planning.md): trees planted at the start of the year, planted
  // trees that died in it, trees a thinning removed at its end and their stem volume.
  std::int64_t planted = 0, diedAfterPlanting = 0, removed = 0;
  double removedVolume_m3PerHa = 0.0;
  double meanHeight_m = 0.0;  // of every plant
  // The forester's measures (stand_measures.hpp), trees of at least 10 cm dbh.
  double stemsPerHa = 0.0;
  double basalArea_m2PerHa = 0.0;
  double qmd_cm = 0.0;
  double dominantHeight_m = 0.0;
  double sdi = 0.0;
  double volume_m3PerHa = 0.0;
  double coverFraction = 0.0;  // share of cell centres under a crown of the species
  // The whole stand's row: the basal area of the densest 1-ha block of the map.
  double densestHectareBasalArea_m2PerHa = 0.0;
};

void writeStatsCsv(const std::filesystem::path& file, const std::vector<StatsRow>& rows,
                   const std::vector<EcosystemSpecies>& species);

// A stats.csv read back: its rows, their species indices into `species` (in order of first
// appearance) or kAllSpecies for the stand's rows.
struct StatsFile {
  std::vector<std::string> species;
  std::vector<StatsRow> rows;
};
// Columns are found by name, so files of earlier versions without the plan's columns read
// with those as 0; a missing column, a bad number or species name is an InputError at its line.
StatsFile readStatsCsv(const std::filesystem::path& file);

// What a species looks like at the end of a run (run.json's final_counts).
struct SpeciesCount {
  std::string name;
  std::int64_t alive = 0;
  std::int64_t over5m = 0;  // taller than 5 m
  // Where those taller than 5 m stand: the mean of each condition field over their cells,
  // in conditionFieldInfo() order (empty where none is that tall).
  std::vector<double> meanSiteOver5m;
  // Where its stems (1.3 m and taller) stand: in canopy gaps and at their edges.
  GapStems gaps;
};

// run.json: what ran, how far it got, and what grew.
struct RunRecord {
  std::string version;
  std::string status;  // running | complete | interrupted | failed
  std::string error;   // why it failed (status "failed")
  std::filesystem::path scenarioFile;
  std::string scenarioName;
  std::uint64_t fingerprint = 0;  // scenarioFingerprint() of the scenario it ran
  std::string scenarioText;       // the scenario file as it was
  std::uint64_t seed = 0;
  int years = 0;
  int lastYear = 0;
  int threads = 0;
  double conditionsSeconds = 0.0, simulationSeconds = 0.0, plantYearsPerSecond = 0.0;
  std::vector<SpeciesCount> counts;
  std::vector<double> meanSite;  // each condition field's mean over the map
  CanopyGapShares canopyGaps;    // of the map at the last year
};

void writeRunJson(const RunPaths& run, const RunRecord& record);
// The record's scenario, fingerprint, status and years; InputError naming run.json when it
// is missing or malformed.
RunRecord readRunJson(const RunPaths& run);

}  // namespace eco

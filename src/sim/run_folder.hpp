// Reading a run folder back (docs/simulation.md): its scenario, the years it holds tree
// snapshots for, and a snapshot's trees. The renderer and exporters read runs only here.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/scenario.hpp"

namespace eco {

struct RunFolder {
  std::filesystem::path dir;
  Scenario scenario;               // as run.json names it
  std::vector<int> snapshotYears;  // ascending; the years of trees/year_NNNN.csv
};

// Throws InputError (naming the folder or run.json) when the folder, run.json or its
// scenario is missing or unreadable.
RunFolder openRunFolder(const std::filesystem::path& dir);

struct TreeRow {
  std::uint64_t id = 0;
  int species = 0;  // index into TreeSnapshot::speciesNames
  double east_m = 0.0, north_m = 0.0, ground_m = 0.0;
  int age_years = 0;
  float height_m = 0.0f, crownRadius_m = 0.0f, dbh_m = 0.0f, vigor = 0.0f;
  std::uint64_t variantSeed = 0;
};

struct TreeSnapshot {
  int year = 0;
  std::vector<std::string> speciesNames;  // in order of first appearance
  std::vector<TreeRow> trees;
};

// An InputError listing the years there are unless the run has a snapshot of `year`.
void requireSnapshotYear(const RunFolder& run, int year);
// The snapshot of `year`; an InputError lists the years there are when it is not one.
TreeSnapshot readSnapshot(const RunFolder& run, int year);
// Parses one trees CSV (the header writeTreesCsv writes); errors give the file and line.
TreeSnapshot readTreesCsv(const std::filesystem::path& file);

}  // namespace eco

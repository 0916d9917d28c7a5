// Reading a run folder back (docs/run_folder.md): its scenario, the years it holds tree
// snapshots for, and a snapshot's trees (run_format.hpp reads the files). The renderer and
// exporters read runs only here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/run/run_format.hpp"
#include "sim/scenario.hpp"

namespace eco {

struct RunFolder {
  std::filesystem::path dir;
  Scenario scenario;               // as run.json names it
  std::vector<int> snapshotYears;  // ascending; the years of trees/year_NNNN.csv or .bin
  // run.json's: running, complete, interrupted or failed; "killed" when it says running
  // but no run holds the folder any more.
  std::string status;
};

// Throws InputError (naming the folder or run.json) when the folder, run.json or its
// scenario is missing or unreadable, or the scenario's files changed since the run.
RunFolder openRunFolder(const std::filesystem::path& dir);

// An InputError listing the years there are unless the run has a snapshot of `year`.
void requireSnapshotYear(const RunFolder& run, int year);
// The snapshot of `year` (only the rows `keep` keeps); an InputError lists the years there
// are when it is not one.
TreeSnapshot readSnapshot(const RunFolder& run, int year, const TreeFilter& keep = {});
// The same a batch of rows at a time (readTreesInBatches), for writing it out.
void readSnapshotInBatches(const RunFolder& run, int year, const TreeFilter& keep,
                           const TreeBatch& each);
// Room for a snapshot read a batch at a time: at least its rows (treeRowsAtMost).
std::size_t snapshotRowsAtMost(const RunFolder& run, int year);
}  // namespace eco

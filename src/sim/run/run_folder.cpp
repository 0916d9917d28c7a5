#include "sim/run/run_folder.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "core/error.hpp"
#include "sim/run/run_lock.hpp"
#include "sim/run/simulation.hpp"

namespace eco {

RunFolder openRunFolder(const std::filesystem::path& dir) {
  if (!std::filesystem::is_directory(dir))
    throw InputError({dir.string(), 0, ""}, "no such run folder");
  RunFolder run;
  run.dir = dir;
  const RunPaths paths{dir};
  const RunRecord record = readRunJson(paths);
  run.scenario = loadScenario(record.scenarioFile);
  // The trees of the run belong to the scenario as it was: on an edited relief, or with an
  // edited species, they would stand on the wrong ground or be drawn as another tree.
  if (record.fingerprint != 0 && scenarioFingerprint(run.scenario) != record.fingerprint)
    throw InputError(
        {paths.runJson().string(), 0, "scenario.fingerprint"},
        fmt::format("the scenario {} (or its heightmap or a species file) has changed since this "
                    "run; run it again, or restore the files the run was made with",
                    record.scenarioFile.string()));
  run.status = record.status;
  if (run.status == "running" && !runIsActive(dir)) run.status = "killed";
  run.snapshotYears = paths.snapshotYears();
  return run;
}

void requireSnapshotYear(const RunFolder& run, int year) {
  if (!std::binary_search(run.snapshotYears.begin(), run.snapshotYears.end(), year)) {
    std::string years;
    for (int y : run.snapshotYears) years += (years.empty() ? "" : ", ") + std::to_string(y);
    throw InputError({run.dir.string(), 0, "year"},
                     fmt::format("the run has no snapshot of year {} (it has: {})", year,
                                 years.empty() ? "none" : years));
  }
}

TreeSnapshot readSnapshot(const RunFolder& run, int year, const TreeFilter& keep) {
  requireSnapshotYear(run, year);
  TreeSnapshot snapshot = readTrees(RunPaths{run.dir}.existingSnapshot(year), keep);
  snapshot.year = year;
  return snapshot;
}

void readSnapshotInBatches(const RunFolder& run, int year, const TreeFilter& keep,
                           const TreeBatch& each) {
  requireSnapshotYear(run, year);
  readTreesInBatches(RunPaths{run.dir}.existingSnapshot(year), keep, each);
}

std::size_t snapshotRowsAtMost(const RunFolder& run, int year) {
  requireSnapshotYear(run, year);
  return treeRowsAtMost(RunPaths{run.dir}.existingSnapshot(year));
}

}  // namespace eco

#include "sim/run/run_folder.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "core/error.hpp"

namespace eco {

RunFolder openRunFolder(const std::filesystem::path& dir) {
  if (!std::filesystem::is_directory(dir))
    throw InputError({dir.string(), 0, ""}, "no such run folder");
  RunFolder run;
  run.dir = dir;
  const RunPaths paths{dir};
  run.scenario = loadScenario(readRunJson(paths).scenarioFile);
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

TreeSnapshot readSnapshot(const RunFolder& run, int year) {
  requireSnapshotYear(run, year);
  TreeSnapshot snapshot = readTreesCsv(RunPaths{run.dir}.snapshot(year));
  snapshot.year = year;
  return snapshot;
}

}  // namespace eco

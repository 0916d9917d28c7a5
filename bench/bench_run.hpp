// What the benchmarks of a grown forest share: a scenario grown, as `ecoforest run` grows
// it, into a fresh folder of the temporary directory, and opened as a run.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "sim/run/run_folder.hpp"
#include "sim/run/simulation.hpp"

namespace eco::bench {

// Grows `scenario` (for `years`, or the scenario's) into TMP/ecoforest_NAME/run, replacing
// what an earlier benchmark left there, and opens it.
inline RunFolder growRun(const std::filesystem::path& scenario, const std::string& name,
                         std::optional<int> years = std::nullopt) {
  const auto work = std::filesystem::temp_directory_path() / ("ecoforest_" + name);
  std::filesystem::remove_all(work);
  std::filesystem::create_directories(work);
  RunOptions run;
  run.scenarioFile = scenario;
  run.out = work / "run";
  run.years = years;
  runSimulation(run);
  return openRunFolder(work / "run");
}

}  // namespace eco::bench

// A whole run of `ecoforest run` (docs/run_folder.md): loads the scenario and its species,
// computes the living conditions, steps the ecosystem year by year and writes the run
// folder — maps, stats.csv, tree snapshots, run.json and a checkpoint after every year,
// each file written whole or not at all.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/hash.hpp"
#include "sim/conditions/conditions.hpp"
#include "sim/ecology/ecosystem.hpp"
#include "sim/run/run_format.hpp"

namespace eco {

struct RunProgress {
  int year = 0;       // the year just finished
  int lastYear = 0;   // the year the run ends with
  int firstYear = 0;  // the first year of this session (after a resume: not 1)
  std::size_t plants = 0;
  double seconds = 0.0;  // since this session's first year began
};

struct RunOptions {
  std::filesystem::path scenarioFile;
  std::optional<std::filesystem::path> out;  // overrides [output] dir
  std::optional<int> years;                  // overrides [simulation] years
  bool resume = false;
  bool ignoreMemoryCheck = false;  // go ahead where the terrain seems too large for memory
  std::string programVersion = "unknown";
  // Checked after every year: once true, the run stops there, its files complete.
  const std::atomic<bool>* stop = nullptr;
  std::function<void(const RunProgress&)> progress;
  std::function<void(const std::string&)> warn;
};

struct RunSummary {
  std::filesystem::path folder;
  int lastYear = 0;  // the last year simulated (and written)
  int targetYears = 0;
  bool interrupted = false;
  std::vector<SpeciesCount> counts;
  std::vector<double> meanSite;  // each condition field's mean over the whole map
  CanopyGapShares canopyGaps;    // of the map at the last year
  double conditionsSeconds = 0.0;
  double simulationSeconds = 0.0;
  double plantYears = 0.0;  // plants stepped, summed over this session's years
};

RunSummary runSimulation(const RunOptions& options);

// A fingerprint of everything that defines a run's ecology: the scenario file, its
// heightmap and its species files.
std::uint64_t scenarioFingerprint(const Scenario& scenario);
// The species files' part of it, continuing `hash`: what the trees are built from.
std::uint64_t speciesFilesFingerprint(const Scenario& scenario, std::uint64_t hash = fnv1a64(""));

// The scenario's species with their ecology and site suitability; errors name the scenario
// line of the species entry at fault.
std::vector<EcosystemSpecies> loadEcosystemSpecies(const Scenario& scenario,
                                                   const ConditionFields& fields);

}  // namespace eco

#include "sim/run/simulation.hpp"

#include <chrono>

#include <fmt/format.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include "core/atomic_file.hpp"
#include "core/binary_io.hpp"
#include "core/error.hpp"
#include "core/names.hpp"
#include "sim/conditions/condition_maps.hpp"
#include "sim/ecology/suitability.hpp"
#include "sim/plan/management.hpp"
#include "sim/run/checkpoint.hpp"
#include "sim/run/run_lock.hpp"
#include "sim/run/run_outputs.hpp"

namespace eco {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A file's bytes; empty if it cannot be read (the scenario and its files were read already).
std::string fileBytes(const std::filesystem::path& file) {
  return readFileBytes(file).value_or(std::string());
}

std::vector<SpeciesCount> countsOf(const Ecosystem& ecosystem, const ConditionFields& fields,
                                   const CanopyGapMap& gaps) {
  const std::vector<FieldInfo>& info = conditionFieldInfo();
  const auto speciesCount = static_cast<int>(ecosystem.species().size());
  const std::vector<GapStems> gapStems = gapStemsOf(ecosystem.plants(), gaps, speciesCount);
  std::vector<SpeciesCount> counts;
  for (int s = 0; s < speciesCount; ++s)
    counts.push_back({ecosystem.species()[s].species.name, 0, 0,
                      std::vector<double>(info.size(), 0.0), gapStems[s]});
  const Plants& p = ecosystem.plants();
  for (std::size_t i = 0; i < p.size(); ++i) {
    SpeciesCount& c = counts[p.species[i]];
    ++c.alive;
    if (p.height_m[i] <= 5.0f) continue;
    ++c.over5m;
    for (std::size_t f = 0; f < info.size(); ++f)
      c.meanSiteOver5m[f] += (fields.*info[f].field)[ecosystem.cellOf(p, i)];
  }
  for (SpeciesCount& c : counts) {
    if (c.over5m == 0) c.meanSiteOver5m.clear();
    for (double& sum : c.meanSiteOver5m) sum /= static_cast<double>(c.over5m);
  }
  return counts;
}

// What grows where, into the summary (run.json's final_counts and canopy_gaps).
void recordCounts(RunSummary& summary, const Ecosystem& ecosystem, const ConditionFields& fields) {
  const CanopyGapMap gaps(ecosystem.plants(), ecosystem.terrain());
  summary.counts = countsOf(ecosystem, fields, gaps);
  summary.canopyGaps = gaps.shares();
}

std::vector<double> meanSiteOf(const ConditionFields& fields) {
  std::vector<double> means;
  for (const FieldInfo& f : conditionFieldInfo()) means.push_back(statsOf(fields.*f.field).mean);
  return means;
}

RunRecord runRecord(const Scenario& scenario, const RunOptions& options, std::uint64_t fingerprint,
                    const RunSummary& summary, std::string status) {
  RunRecord r;
  r.version = options.programVersion;
  r.status = std::move(status);
  r.scenarioFile = scenario.file;
  r.scenarioName = scenario.name;
  r.fingerprint = fingerprint;
  r.scenarioText = fileBytes(scenario.file);
  r.seed = scenario.seed;
  r.years = summary.targetYears;
  r.lastYear = summary.lastYear;
  r.threads = tbb::this_task_arena::max_concurrency();
  r.conditionsSeconds = summary.conditionsSeconds;
  r.simulationSeconds = summary.simulationSeconds;
  r.plantYearsPerSecond =
      summary.simulationSeconds > 0.0 ? summary.plantYears / summary.simulationSeconds : 0.0;
  r.counts = summary.counts;
  r.meanSite = summary.meanSite;
  r.canopyGaps = summary.canopyGaps;
  return r;
}

// Temporaries of writes a kill -9 or a power cut interrupted (AtomicFile's NAME.tmp-PID-N
// and the frame sinks' .partial_NAME): no process writes them any more once this run holds
// the lock.
void removeStaleTemporaries(const RunPaths& run) {
  for (const std::filesystem::path& folder :
       {run.dir, run.treesFolder(), run.mapsFolder(), run.removedFolder()}) {
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
      const std::string name = entry.path().filename().string();
      if (entry.is_regular_file(error) &&
          (isAtomicTemporary(name) || name.starts_with(".partial_")))
        std::filesystem::remove(entry.path(), error);
    }
  }
}

// What an earlier run wrote that this one may not rewrite: its snapshots (this run may
// write fewer), its thinnings, checkpoint, statistics and maps (of species this run may not
// have).
void removeEarlierRun(const RunPaths& run) {
  for (const std::filesystem::path& folder :
       {run.treesFolder(), run.mapsFolder(), run.removedFolder()}) {
    if (!std::filesystem::is_directory(folder)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.is_regular_file()) std::filesystem::remove(entry.path());
  }
  std::filesystem::remove(run.checkpoint());
  std::filesystem::remove(run.stats());
}

RunSummary simulateInto(const Scenario& scenario, const std::filesystem::path& folder,
                        const RunOptions& options, std::optional<RunRecord>& claimed);

}  // namespace

std::uint64_t scenarioFingerprint(const Scenario& scenario) {
  std::uint64_t hash = fnv1a64(fileBytes(scenario.file));
  if (scenario.terrain.heightmap) hash = fnv1a64(fileBytes(*scenario.terrain.heightmap), hash);
  return speciesFilesFingerprint(scenario, hash);
}

std::uint64_t speciesFilesFingerprint(const Scenario& scenario, std::uint64_t hash) {
  for (const ScenarioSpecies& s : scenario.species) hash = fnv1a64(fileBytes(s.file), hash);
  return hash;
}

std::vector<EcosystemSpecies> loadEcosystemSpecies(const Scenario& scenario,
                                                   const ConditionFields& fields) {
  if (scenario.species.empty())
    throw InputError({scenario.file.string(), 0, "species"},
                     "the scenario lists no species: add [[species]] tables with a file each");
  if (scenario.species.size() > 255)
    throw InputError(scenario.species[255].where, "at most 255 species per scenario");
  std::vector<EcosystemSpecies> result;
  for (const ScenarioSpecies& entry : scenario.species) {
    EcosystemSpecies s = readEcosystemSpecies(entry.file, entry.where);
    s.seedRainPerHaPerYear = entry.seedRainPerHaPerYear;
    s.surroundingForestShare = entry.surroundingForestShare;
    s.suitability = siteSuitability(s.ecology.tolerances(scenario.climate), fields,
                                    scenario.simulation.suitability);
    result.push_back(std::move(s));
  }
  return result;
}

RunSummary runSimulation(const RunOptions& options) {
  const Scenario scenario = loadScenario(options.scenarioFile);
  const std::filesystem::path folder = options.out.value_or(scenario.output.dir);
  RunLock lock(folder);
  removeStaleTemporaries(RunPaths{folder});
  // Once this run has claimed the folder (run.json says "running"), an error leaves run.json
  // saying "failed" and why, never "running" or an earlier run's "complete".
  std::optional<RunRecord> claimed;
  try {
    return simulateInto(scenario, folder, options, claimed);
  } catch (const std::exception& error) {
    if (!claimed) {
      lock.abandon();  // refused before anything was written: the folder is as it was
      throw;
    }
    claimed->status = "failed";
    claimed->error = error.what();
    try {
      writeRunJson(RunPaths{folder}, *claimed);
    } catch (const std::exception&) {
      // The disk that failed the run may fail this too; the run's own error is reported.
    }
    throw;
  }
}

namespace {

RunSummary simulateInto(const Scenario& scenario, const std::filesystem::path& folder,
                        const RunOptions& options, std::optional<RunRecord>& claimed) {
  RunSummary summary;
  summary.targetYears = options.years.value_or(scenario.simulation.years);
  if (summary.targetYears < 1)
    throw InputError({scenario.file.string(), 0, "years"}, "years must be at least 1");
  summary.folder = folder;
  const RunPaths run{summary.folder};
  const std::uint64_t fingerprint = scenarioFingerprint(scenario);
  if (std::all_of(scenario.species.begin(), scenario.species.end(),
                  [](const ScenarioSpecies& s) {
                    return s.seedRainPerHaPerYear <= 0.0 && s.surroundingForestShare <= 0.0;
                  }) &&
      scenario.plan.planting.empty() && scenario.plan.seedSources.empty() &&
      !scenario.species.empty() && options.warn)
    options.warn(fmt::format(
        "{}: no species has a seed rain or a share of the surrounding forest, there is no "
        "seed source, nothing is planted, and the landscape starts empty, so nothing will grow",
        scenario.file.string()));

  // Read the checkpoint before anything is written, so a refused resume changes nothing.
  std::optional<Checkpoint> checkpoint;
  if (options.resume) checkpoint = readCheckpoint(run.checkpoint(), fingerprint);

  const auto conditionsStart = Clock::now();
  Terrain terrain = loadTerrain(scenario);
  requireMemoryForConditions(terrain.grid, options.ignoreMemoryCheck);
  ConditionsReport report;
  ConditionFields fields =
      computeConditions(terrain, scenario.climate, SunlightSettings{}, &report);
  std::vector<EcosystemSpecies> species = loadEcosystemSpecies(scenario, fields);
  if (checkpoint)
    checkCheckpoint(*checkpoint, {terrain.grid, species.size(), summary.targetYears},
                    run.checkpoint());
  summary.conditionsSeconds = secondsSince(conditionsStart);

  EcosystemSettings settings{scenario.seed, scenario.climate.prevailingWindFrom_deg};
  Ecosystem ecosystem(terrain, fields, std::move(species), settings);
  // The plan's regions and species are checked before anything is written.
  Management plan(scenario.plan, ecosystem, scenario.seed);
  std::vector<StatsRow> stats;
  createOutputFolder(run.mapsFolder());
  createOutputFolder(run.treesFolder());
  if (!scenario.plan.thinning.empty()) createOutputFolder(run.removedFolder());
  if (checkpoint) {
    ecosystem.restore(std::move(checkpoint->state));
    stats = std::move(checkpoint->stats);
  } else {
    // A fresh run replaces whatever an earlier run left in the folder. run.json says so
    // first: a run killed while the old files go would otherwise leave a run.json claiming
    // the old run's years over a folder without them.
    claimed = runRecord(scenario, options, fingerprint, summary, "running");
    writeRunJson(run, *claimed);
    removeEarlierRun(run);
    writeConditionOutputs(fields, report, scenario, summary.folder);
    if (!scenario.plan.empty())
      writeFieldMap(run.mapsFolder(), "plan", "0-4", maskOutside(terrain, plan.planMap()),
                    terrain.grid);
    for (const EcosystemSpecies& s : ecosystem.species())
      writeFieldMap(run.mapsFolder(), "suitability_" + s.species.name, "0-1",
                    maskOutside(terrain, s.suitability), terrain.grid);
  }
  summary.lastYear = ecosystem.year();
  summary.meanSite = meanSiteOf(fields);
  recordCounts(summary, ecosystem, fields);
  claimed = runRecord(scenario, options, fingerprint, summary, "running");
  writeRunJson(run, *claimed);

  // The snapshots and checkpoints wait for the disk (fsync) and are renamed into place while
  // the next years grow; the run is complete once they are in place.
  BackgroundCommits commits;
  const auto start = Clock::now();
  const int firstYear = ecosystem.year() + 1;
  while (ecosystem.year() < summary.targetYears) {
    PlanYear done(ecosystem.species().size());
    plan.plantAtStartOf(ecosystem.year() + 1, done, options.warn);
    summary.plantYears += static_cast<double>(ecosystem.plants().size());
    ecosystem.step();
    const int year = ecosystem.year();
    plan.thinAtEndOf(year, done);
    if (done.removedPlants.size() > 0)
      writeTrees(run.removed(year), ecosystem, done.removedPlants, SnapshotFormat::Csv);
    std::vector<StatsRow> rows = statsOfYear(ecosystem, done);
    stats.insert(stats.end(), rows.begin(), rows.end());
    writeStatsCsv(run.stats(), stats, ecosystem.species());
    const bool last = year == summary.targetYears;
    if (year % scenario.output.snapshotEveryYears == 0 || last) {
      AtomicFile snapshotFile(run.snapshot(year, scenario.output.snapshotFormat));
      writeTrees(snapshotFile, ecosystem, ecosystem.plants(), scenario.output.snapshotFormat);
      commits.commit(std::move(snapshotFile));
    }
    summary.lastYear = year;
    if (options.progress)
      options.progress(
          {year, summary.targetYears, firstYear, ecosystem.plants().size(), secondsSince(start)});
    const bool stopping = options.stop && options.stop->load() && !last;
    if (year % scenario.output.checkpointEveryYears == 0 || last || stopping) {
      AtomicFile checkpointFile(run.checkpoint());
      writeCheckpoint(checkpointFile, fingerprint, options.programVersion, ecosystem.state(),
                      stats);
      commits.commit(std::move(checkpointFile));
    }
    if (stopping) {
      summary.interrupted = true;
      break;
    }
  }
  commits.wait();
  summary.simulationSeconds = secondsSince(start);
  recordCounts(summary, ecosystem, fields);
  if (!summary.interrupted)
    writeFieldMap(run.mapsFolder(), "canopy_height", "m",
                  maskOutside(terrain, canopyHeight(ecosystem)), terrain.grid);
  claimed = runRecord(scenario, options, fingerprint, summary,
                      summary.interrupted ? "interrupted" : "complete");
  writeRunJson(run, *claimed);
  return summary;
}

}  // namespace

}  // namespace eco

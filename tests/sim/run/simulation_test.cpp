#include "sim/run/simulation.hpp"

#include <map>
#include <utility>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "core/error.hpp"
#include "sim/run/checkpoint.hpp"
#include "sim/run/run_lock.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

std::string speciesFile(const std::string& name) {
  return (std::filesystem::path(ECOFOREST_DATA_DIR) / "species" / (name + ".toml")).string();
}

// A small generated landscape with the valley's species; `extra` is appended.
std::filesystem::path smallScenario(const std::string& name, const std::string& extra = "",
                                    double beechRain = 3.0) {
  const auto folder = test::freshDirectory("simulation_" + name);
  const std::string text = R"(name = ")" + name + R"("
seed = 5
[terrain]
cell_size_m = 10.0
[terrain.generate]
size = 33
relief_m = 60.0
base_altitude_m = 400.0
[simulation]
years = 30
[[species]]
file = ")" + speciesFile("beech") +
                           R"("
seed_rain_per_ha_per_year = )" +
                           std::to_string(beechRain) + R"(
[[species]]
file = ")" + speciesFile("pine") +
                           R"("
seed_rain_per_ha_per_year = 3.0
[[species]]
file = ")" + speciesFile("shrub") +
                           R"("
seed_rain_per_ha_per_year = 3.0
[output]
snapshot_every_years = 10
)" + extra;
  test::writeFile(folder / "scenario.toml", text);
  return folder / "scenario.toml";
}

RunOptions optionsFor(const std::filesystem::path& scenario, const std::filesystem::path& out) {
  RunOptions o;
  o.scenarioFile = scenario;
  o.out = out;
  return o;
}

// The outputs that must not depend on threads or interruptions (run.json holds timings).
std::vector<std::string> outputsOf(const std::filesystem::path& folder) {
  std::vector<std::string> files = {test::readFile(folder / "stats.csv"),
                                    test::readFile(folder / "maps/canopy_height.exr")};
  for (int year : {10, 20, 30})
    files.push_back(test::readFile(folder / "trees" / ("year_00" + std::to_string(year) + ".csv")));
  return files;
}

TEST(Simulation, WritesTheRunFolder) {
  const auto scenario = smallScenario("folder");
  const auto out = test::freshDirectory("simulation_folder_out");
  const RunSummary summary = runSimulation(optionsFor(scenario, out));
  EXPECT_EQ(summary.lastYear, 30);
  EXPECT_FALSE(summary.interrupted);
  for (const char* file :
       {"run.json", "stats.csv", "checkpoint.bin", "conditions.json", "trees/year_0010.csv",
        "trees/year_0030.csv", "maps/moisture.png", "maps/suitability_beech.png",
        "maps/suitability_pine.exr", "maps/canopy_height.png"})
    EXPECT_TRUE(std::filesystem::exists(out / file)) << file;
  const std::string stats = test::readFile(out / "stats.csv");
  // A header, then each year a row per species (three) and one for the whole stand.
  EXPECT_EQ(std::count(stats.begin(), stats.end(), '\n'), 1 + 30 * 4);
  const std::string json = test::readFile(out / "run.json");
  EXPECT_NE(json.find("\"status\": \"complete\""), std::string::npos);
  EXPECT_NE(json.find("\"fingerprint\""), std::string::npos);
  EXPECT_NE(json.find("\"mean_site_of_map\""), std::string::npos);
  EXPECT_NE(json.find("\"mean_site_taller_than_5m\""), std::string::npos);
  // Where the taller plants stand: a mean of each condition over their cells, so within
  // the terrain's altitudes (base 400 m, relief 60 m), Ellenberg's F scale for moisture and
  // the 0..1 of the unitless fields.
  ASSERT_EQ(summary.meanSite.size(), conditionFieldInfo().size());
  int speciesWithTallPlants = 0;
  for (const SpeciesCount& c : summary.counts) {
    if (c.over5m == 0) {
      EXPECT_TRUE(c.meanSiteOver5m.empty());
      continue;
    }
    ++speciesWithTallPlants;
    ASSERT_EQ(c.meanSiteOver5m.size(), summary.meanSite.size());
    for (std::size_t f = 0; f < c.meanSiteOver5m.size(); ++f) {
      const std::string name = conditionFieldInfo()[f].name;
      if (name == "altitude") {
        EXPECT_GT(c.meanSiteOver5m[f], 340.0);
        EXPECT_LT(c.meanSiteOver5m[f], 520.0);
      } else if (name == "moisture") {
        EXPECT_GE(c.meanSiteOver5m[f], 1.0) << name;
        EXPECT_LE(c.meanSiteOver5m[f], 12.0) << name;
      } else if (name == "windiness" || name == "sunniness") {
        EXPECT_GE(c.meanSiteOver5m[f], 0.0) << name;
        EXPECT_LE(c.meanSiteOver5m[f], 1.0) << name;
      }
    }
  }
  EXPECT_GT(speciesWithTallPlants, 0);
  // Where the stems stand (canopy_gaps.hpp): shares, each species' stems among its plants,
  // and the same in run.json.
  EXPECT_NE(json.find("\"canopy_gaps\""), std::string::npos);
  EXPECT_NE(json.find("\"stems_in_gaps_or_edges\""), std::string::npos);
  EXPECT_GE(summary.canopyGaps.gapsOrEdges, summary.canopyGaps.gaps);
  EXPECT_LE(summary.canopyGaps.gapsOrEdges, 1.0);
  std::int64_t stems = 0;
  for (const SpeciesCount& c : summary.counts) {
    EXPECT_LE(c.gaps.stems, c.alive);
    EXPECT_GE(c.gaps.shares.gaps, 0.0);
    EXPECT_LE(c.gaps.shares.gaps, c.gaps.shares.gapsOrEdges);
    EXPECT_LE(c.gaps.shares.gapsOrEdges, 1.0);
    stems += c.gaps.stems;
  }
  EXPECT_GT(stems, 0);
}

TEST(Simulation, SameOutputsWithOneAndTwoThreads) {
  const auto scenario = smallScenario("threads");
  auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const auto out = test::freshDirectory("simulation_threads_" + std::to_string(threads));
    runSimulation(optionsFor(scenario, out));
    return outputsOf(out);
  };
  EXPECT_TRUE(run(1) == run(2));
}

TEST(Simulation, ResumedRunEndsWithTheSameOutputsAsAnUninterruptedOne) {
  const auto scenario = smallScenario("resume");
  const auto whole = test::freshDirectory("simulation_whole");
  runSimulation(optionsFor(scenario, whole));

  const auto pieces = test::freshDirectory("simulation_pieces");
  std::atomic<bool> stop{false};
  RunOptions first = optionsFor(scenario, pieces);
  first.stop = &stop;
  first.progress = [&](const RunProgress& p) { stop = p.year >= 13; };
  const RunSummary interrupted = runSimulation(first);
  EXPECT_TRUE(interrupted.interrupted);
  EXPECT_EQ(interrupted.lastYear, 13);
  EXPECT_NE(test::readFile(pieces / "run.json").find("\"interrupted\""), std::string::npos);

  RunOptions rest = optionsFor(scenario, pieces);
  rest.resume = true;
  int firstYear = 0;
  rest.progress = [&](const RunProgress& p) { firstYear = p.firstYear; };
  EXPECT_EQ(runSimulation(rest).lastYear, 30);
  EXPECT_EQ(firstYear, 14);
  EXPECT_TRUE(outputsOf(whole) == outputsOf(pieces));
}

// With a checkpoint every 5 years, the checkpoint lags the run by up to 4 years; a stopped run
// still writes one for the year it stops at, and resumes to the same outputs.
TEST(Simulation, CheckpointsEveryFewYearsStillResumeExactly) {
  const auto scenario = smallScenario("every5", "checkpoint_every_years = 5\n");
  const auto whole = test::freshDirectory("simulation_every5_whole");
  runSimulation(optionsFor(scenario, whole));
  const auto pieces = test::freshDirectory("simulation_every5_pieces");
  std::atomic<bool> stop{false};
  RunOptions first = optionsFor(scenario, pieces);
  first.stop = &stop;
  std::vector<std::pair<int, int>> checkpointAtYear;  // the checkpoint on disk at a progress
  const std::uint64_t fingerprint = scenarioFingerprint(loadScenario(scenario));
  first.progress = [&](const RunProgress& p) {
    if (std::filesystem::exists(pieces / "checkpoint.bin"))
      checkpointAtYear.emplace_back(
          p.year, readCheckpoint(pieces / "checkpoint.bin", fingerprint).state.year);
    stop = p.year >= 13;
  };
  EXPECT_TRUE(runSimulation(first).interrupted);
  // Checkpoints are committed in the background: at a year's progress the checkpoint on disk
  // is one of an earlier year that is a multiple of 5 (year 5's, then year 10's once it is in
  // place), never going back; the interrupted run's own is in place when the run returns.
  int before = 0;
  for (const auto& [year, checkpoint] : checkpointAtYear) {
    EXPECT_TRUE(checkpoint % 5 == 0 && checkpoint > 0 && checkpoint < year) << year;
    EXPECT_GE(checkpoint, before) << year;
    before = checkpoint;
  }
  EXPECT_EQ(readCheckpoint(pieces / "checkpoint.bin", fingerprint).state.year, 13);
  RunOptions rest = optionsFor(scenario, pieces);
  rest.resume = true;
  EXPECT_EQ(runSimulation(rest).lastYear, 30);
  EXPECT_TRUE(outputsOf(whole) == outputsOf(pieces));
}

// Every kind of rule at once on the small landscape (330 m x 330 m).
const char* kEveryRule = R"(
[[planting]]
species = { beech = 0.6, pine = 0.4 }
polygon = [[0, 0], [150, 0], [150, 150], [0, 150]]
layout = "triangular"
spacing_m = 3
[[planting]]
rows = ["pine", "beech"]
year = 5
layout = "contour"
spacing_m = 3
polygon = [[170, 170], [320, 170], [320, 320], [170, 320]]
age_years = 2
[[seed_source]]
species = { beech = 0.8, pine = 0.2 }
border_m = 200
cover = 0.9
[[exclusion]]
line = [[-10, 160], [340, 160]]
buffer_m = 4
[[thinning]]
method = "from_below"
from_year = 15
every_years = 5
target_stems_per_ha = 300
polygon = [[0, 0], [150, 0], [150, 150], [0, 150]]
[[thinning]]
method = "remove_species"
species = ["pine"]
from_year = 25
every_years = 5
polygon = [[170, 170], [320, 170], [320, 320], [170, 320]]
)";

std::vector<std::string> planOutputsOf(const std::filesystem::path& folder) {
  std::vector<std::string> files = outputsOf(folder);
  files.push_back(test::readFile(folder / "maps/plan.exr"));
  for (const auto& entry : std::filesystem::directory_iterator(folder / "removed"))
    files.push_back(entry.path().filename().string() + test::readFile(entry.path()));
  return files;
}

TEST(Simulation, APlanIsCarriedOutAndCounted) {
  const auto scenario = smallScenario("plan", kEveryRule, 0.0);
  const auto out = test::freshDirectory("simulation_plan_out");
  std::vector<std::string> warnings;
  RunOptions options = optionsFor(scenario, out);
  options.warn = [&](const std::string& w) { warnings.push_back(w); };
  runSimulation(options);
  const StatsFile stats = readStatsCsv(out / "stats.csv");
  std::map<int, StatsRow> stand;
  for (const StatsRow& r : stats.rows)
    if (r.species == kAllSpecies) stand[r.year] = r;
  EXPECT_GT(stand[1].planted, 2000);  // 2.25 ha at 3 m triangular, less the ride
  EXPECT_GT(stand[5].planted, 1000);
  for (int year : {2, 3, 4, 6}) EXPECT_EQ(stand[year].planted, 0) << year;
  EXPECT_GT(stand[30].removed, 0);  // the pines of the contour rows go in year 25
  EXPECT_GT(stand[25].removed, 0);
  for (int year = 1; year <= 30; ++year)
    EXPECT_EQ(std::filesystem::exists(out / fmt::format("removed/year_{:04d}.csv", year)),
              stand[year].removed > 0)
        << year;
  EXPECT_TRUE(std::filesystem::exists(out / "maps/plan.png"));
  // Nothing stands in the ride, and no pine is left in the contour block at a removal.
  const TreeSnapshot last = readTrees(out / "trees/year_0030.csv");
  const auto pine = std::find(last.speciesNames.begin(), last.speciesNames.end(), "pine");
  for (const TreeRow& t : last.trees) {
    EXPECT_GT(std::abs(t.north_m - 160.0), 4.0);
    if (pine != last.speciesNames.end() && t.species == pine - last.speciesNames.begin() &&
        t.east_m > 170 && t.north_m > 170 && t.east_m < 320 && t.north_m < 320)
      ADD_FAILURE() << "a pine at " << t.east_m << ", " << t.north_m;
  }
  // The forest around the map seeds it: seedlings arrive without any seed rain.
  EXPECT_GT(stand[30].alive, stand[1].planted + stand[5].planted);
}

TEST(Simulation, APlanGivesTheSameOutputsWithOneAndTwoThreadsAndAfterAResume) {
  const auto scenario = smallScenario("plan_threads", kEveryRule);
  auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const auto out = test::freshDirectory("simulation_plan_threads_" + std::to_string(threads));
    runSimulation(optionsFor(scenario, out));
    return planOutputsOf(out);
  };
  const std::vector<std::string> whole = run(2);
  EXPECT_TRUE(run(1) == whole);
  // Stopped in year 17, between the first two thinnings and after both plantings.
  const auto pieces = test::freshDirectory("simulation_plan_pieces");
  std::atomic<bool> stop{false};
  RunOptions first = optionsFor(scenario, pieces);
  first.stop = &stop;
  first.progress = [&](const RunProgress& p) { stop = p.year >= 17; };
  EXPECT_TRUE(runSimulation(first).interrupted);
  RunOptions rest = optionsFor(scenario, pieces);
  rest.resume = true;
  runSimulation(rest);
  EXPECT_TRUE(planOutputsOf(pieces) == whole);
}

TEST(Simulation, RefusesToResumeAnotherScenariosCheckpoint) {
  const auto out = test::freshDirectory("simulation_foreign");
  RunOptions options = optionsFor(smallScenario("foreign_a"), out);
  options.years = 2;
  runSimulation(options);
  RunOptions other = optionsFor(smallScenario("foreign_b", "", 1.0), out);
  other.resume = true;
  try {
    runSimulation(other);
    FAIL() << "resumed a foreign checkpoint";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("another scenario"), std::string::npos) << e.what();
  }
}

TEST(Simulation, ASecondRunIntoTheSameFolderIsRefused) {
  const auto out = test::freshDirectory("simulation_locked_out");
  const RunLock otherRun(out);
  try {
    runSimulation(optionsFor(smallScenario("locked"), out));
    FAIL() << "two runs wrote one folder";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("another ecoforest run"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(out / "run.json"));
}

// A fresh run replaces an earlier run's files, and its run.json says so before the old
// files go; what a kill -9 left half-written is cleared away.
TEST(Simulation, AFreshRunLeavesNothingOfAnEarlierOne) {
  const auto out = test::freshDirectory("simulation_reused");
  runSimulation(optionsFor(smallScenario("reused_long"), out));
  EXPECT_TRUE(std::filesystem::exists(out / "trees/year_0030.csv"));
  test::writeFile(out / "stats.csv.tmp-999999-0", "half a file");
  test::writeFile(out / "trees/year_0040.csv.tmp-999999-3", "half a file");
  RunOptions shorter = optionsFor(smallScenario("reused_short"), out);
  shorter.years = 10;
  runSimulation(shorter);
  EXPECT_EQ(RunPaths{out}.snapshotYears(), std::vector<int>{10});
  EXPECT_FALSE(std::filesystem::exists(out / "stats.csv.tmp-999999-0"));
  EXPECT_FALSE(std::filesystem::exists(out / "trees/year_0040.csv.tmp-999999-3"));
  const RunRecord record = readRunJson(RunPaths{out});
  EXPECT_EQ(record.status, "complete");
  EXPECT_EQ(record.lastYear, 10);
}

// A run that fails after it claimed the folder says so in run.json.
TEST(Simulation, AFailedRunIsRecordedAsFailed) {
  const auto out = test::freshDirectory("simulation_failed");
  // A folder where year 10's snapshot must go: the rename onto it fails.
  std::filesystem::create_directories(out / "trees/year_0010.csv/blocked");
  EXPECT_THROW(runSimulation(optionsFor(smallScenario("failing"), out)), EnvironmentError);
  const RunRecord record = readRunJson(RunPaths{out});
  EXPECT_EQ(record.status, "failed");
  EXPECT_NE(record.error.find("year_0010.csv"), std::string::npos) << record.error;
  EXPECT_EQ(test::entriesIn(out / "trees"), 1u);  // the blocking folder; no temporary
}

TEST(Simulation, BadScenariosGiveClearErrors) {
  auto errorOf = [](const std::filesystem::path& scenario) -> std::string {
    try {
      RunOptions o = optionsFor(scenario, test::freshDirectory("simulation_bad_out"));
      o.years = 1;
      runSimulation(o);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  const auto folder = test::freshDirectory("simulation_bad");
  test::writeFile(folder / "missing.toml", R"(name = "x"
[terrain.generate]
size = 17
[[species]]
file = "species/oak.toml"
)");
  EXPECT_NE(errorOf(folder / "missing.toml")
                .find("missing.toml:5: species[0].file: species file not found"),
            std::string::npos)
      << errorOf(folder / "missing.toml");
  test::writeFile(folder / "negative.toml", R"(name = "x"
[terrain.generate]
size = 17
[simulation]
years = -5
)");
  EXPECT_NE(errorOf(folder / "negative.toml").find("negative.toml:5: simulation.years: value -5"),
            std::string::npos)
      << errorOf(folder / "negative.toml");
  test::writeFile(folder / "none.toml", "name = \"x\"\n[terrain.generate]\nsize = 17\n");
  EXPECT_NE(errorOf(folder / "none.toml").find("no species"), std::string::npos);
  // Planting a species the scenario lacks is refused before the run folder is touched.
  test::writeFile(folder / "oak.toml",
                  "name = \"x\"\n[terrain.generate]\nsize = 17\n"
                  "[[species]]\nfile = \"" +
                      speciesFile("beech") + "\"\n[[planting]]\nspecies = \"oak\"\n");
  const auto out = test::freshDirectory("simulation_bad_planting");
  try {
    runSimulation(optionsFor(folder / "oak.toml", out));
    ADD_FAILURE() << "planted an unknown species";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("oak.toml:7: planting[0].species: no species 'oak'"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(std::filesystem::is_empty(out));
  // So is a plan's polygon off the map, before anything is written.
  test::writeFile(folder / "off.toml",
                  "name = \"x\"\n[terrain.generate]\nsize = 17\n[[species]]\nfile = \"" +
                      speciesFile("beech") +
                      "\"\n[[exclusion]]\npolygon = [[5000, 0], [6000, 0], [6000, 900]]\n");
  const auto offOut = test::freshDirectory("simulation_bad_polygon");
  try {
    runSimulation(optionsFor(folder / "off.toml", offOut));
    ADD_FAILURE() << "a polygon off the map was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("off.toml:7: exclusion[0].polygon: the polygon lies "
                                         "outside the map"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(std::filesystem::is_empty(offOut));
}

TEST(Simulation, WarnsWhenNothingCanArrive) {
  RunOptions options =
      optionsFor(smallScenario("no_rain", "", 0.0), test::freshDirectory("simulation_no_rain"));
  // Only beech's rain is zero here: no warning.
  std::vector<std::string> warnings;
  options.warn = [&](const std::string& w) { warnings.push_back(w); };
  options.years = 1;
  runSimulation(options);
  EXPECT_TRUE(warnings.empty());

  const auto folder = test::freshDirectory("simulation_zero");
  test::writeFile(folder / "zero.toml", R"(name = "zero"
[terrain.generate]
size = 17
[[species]]
file = ")" + speciesFile("beech") + R"("
)");
  options = optionsFor(folder / "zero.toml", folder / "out");
  options.warn = [&](const std::string& w) { warnings.push_back(w); };
  options.years = 3;
  runSimulation(options);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("nothing will grow"), std::string::npos);
}

}  // namespace
}  // namespace eco

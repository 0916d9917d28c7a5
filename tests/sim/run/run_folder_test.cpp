#include "sim/run/run_folder.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "sim/run/run_lock.hpp"
#include "sim/run/simulation.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

TEST(RunFolder, AFolderWithoutRunJsonIsNotARun) {
  const auto dir = test::freshDirectory("run_folder_none");
  EXPECT_THROW(openRunFolder(dir), InputError);
  EXPECT_THROW(openRunFolder(dir / "missing"), InputError);
}

// render, view, timelapse and export read a run with the scenario it names: once the
// scenario, its heightmap or a species file changed, the run's trees no longer belong to it.
TEST(RunFolder, AnEditedScenarioNoLongerOpensItsRun) {
  const auto folder = test::freshDirectory("run_folder_edited");
  const std::string beech =
      (std::filesystem::path(ECOFOREST_DATA_DIR) / "species" / "beech.toml").string();
  const std::string scenario =
      "name = \"edited\"\nseed = 3\n[terrain]\ncell_size_m = 10.0\n"
      "[terrain.generate]\nsize = 17\nrelief_m = 20.0\n"
      "[simulation]\nyears = 2\n[[species]]\nfile = \"" +
      beech + "\"\nseed_rain_per_ha_per_year = 5.0\n";
  test::writeFile(folder / "s.toml", scenario);
  RunOptions options;
  options.scenarioFile = folder / "s.toml";
  options.out = folder / "run";
  runSimulation(options);
  const RunFolder run = openRunFolder(folder / "run");
  EXPECT_EQ(run.status, "complete");
  EXPECT_EQ(run.snapshotYears, std::vector<int>{2});

  test::writeFile(folder / "s.toml", scenario + "# relief edited\n");
  try {
    openRunFolder(folder / "run");
    FAIL() << "opened a run under an edited scenario";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("has changed since this run"), std::string::npos)
        << e.what();
    EXPECT_EQ(e.where().file, (folder / "run" / "run.json").string());
  }
}

// run.json says "running", but no run holds the folder: the run was killed.
TEST(RunFolder, ARunningRunWithoutItsLockWasKilled) {
  const auto folder = test::freshDirectory("run_folder_killed");
  test::writeFile(folder / "s.toml", "name = \"k\"\n[terrain.generate]\nsize = 9\n");
  RunRecord record;
  record.status = "running";
  record.scenarioFile = folder / "s.toml";
  writeRunJson(RunPaths{folder}, record);
  EXPECT_EQ(openRunFolder(folder).status, "killed");
  const RunLock running(folder);
  EXPECT_EQ(openRunFolder(folder).status, "running");
}

}  // namespace
}  // namespace eco

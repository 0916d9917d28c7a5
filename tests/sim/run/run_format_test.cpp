#include "sim/run/run_format.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "ecosystem_support.hpp"
#include "sim/run/run_outputs.hpp"
#include "terrain_support.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

using test::OneHectare;

TEST(RunFormat, RunJsonIsCheckedAsUntrustedInput) {
  const RunPaths run{test::freshDirectory("run_format_json_bad")};
  auto faultOf = [&](const std::string& json) {
    test::writeFile(run.runJson(), json);
    try {
      readRunJson(run);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string scenario = R"("scenario": {"file": "s.toml", "fingerprint": "00ff"})";
  EXPECT_EQ(faultOf("{" + scenario + R"(, "status": "complete", "years": 3})"), "no error");
  EXPECT_NE(faultOf("[1, 2]").find("scenario: missing"), std::string::npos);
  EXPECT_NE(faultOf(R"({"scenario": {"file": 7}})").find("scenario.file: expected a string"),
            std::string::npos);
  EXPECT_NE(faultOf("{" + scenario + R"(, "status": "complete", "years": "many"})")
                .find("years: expected a whole number"),
            std::string::npos);
  EXPECT_NE(
      faultOf("{" + scenario + R"(, "status": "complete", "last_year": -4})").find("last_year"),
      std::string::npos);
  EXPECT_NE(faultOf("{" + scenario + R"(, "status": "finished"})").find("status"),
            std::string::npos);
  EXPECT_NE(faultOf(R"({"status": "complete", "scenario": {"file": "s", "fingerprint": "xyz"}})")
                .find("hexadecimal"),
            std::string::npos);
  EXPECT_NE(faultOf("{" + scenario + R"(, "status": "complete", "seed": -1})").find("seed"),
            std::string::npos);
}

TEST_F(OneHectare, CsvFilesHaveTheDocumentedColumns) {
  ecosystem.plant(0, 12.0, 33.0, 40);
  const auto folder = test::freshDirectory("run_outputs");
  writeTrees(folder / "trees.csv", ecosystem, ecosystem.plants(), SnapshotFormat::Csv);
  writeStatsCsv(folder / "stats.csv", statsOfYear(ecosystem, PlanYear(ecosystem.species().size())),
                ecosystem.species());
  const std::string trees = test::readFile(folder / "trees.csv");
  EXPECT_EQ(trees.substr(0, trees.find('\n')),
            "id,species,x_m,y_m,z_m,age,height_m,crown_radius_m,crown_base_m,dbh_m,vigor,"
            "variant_seed,light_east,light_north,wind_east,wind_north");
  EXPECT_NE(trees.find("\n1,t,12.000,33.000,50.000,40,"), std::string::npos) << trees;
  EXPECT_NE(trees.find(",0.00,0.00,0.00,0.00\n"), std::string::npos) << trees;  // no year yet
  const std::string stats = test::readFile(folder / "stats.csv");
  EXPECT_EQ(stats.substr(0, stats.find('\n')),
            "year,species,alive,born,died,mean_height_m,stems_per_ha,basal_area_m2_per_ha,qmd_cm,"
            "dominant_height_m,sdi,volume_m3_per_ha,cover_fraction,"
            "densest_hectare_basal_area_m2_per_ha,planted,died_after_planting,removed,"
            "removed_volume_m3_per_ha");
  EXPECT_NE(stats.find("\n0,t,1,0,0,"), std::string::npos) << stats;
  EXPECT_NE(stats.find("\n0,all,1,0,0,"), std::string::npos) << stats;
}

TEST_F(OneHectare, TheStatsReaderReadsWhatTheWriterWrote) {
  ecosystem.plant(0, 12.0, 33.0, 40);
  ecosystem.step();
  PlanYear plan(1);
  plan.planted[0] = 12;
  plan.removed[0] = 3;
  plan.removedVolume_m3[0] = 4.5;
  const auto folder = test::freshDirectory("run_format_stats");
  const std::vector<StatsRow> rows = statsOfYear(ecosystem, plan);
  writeStatsCsv(folder / "stats.csv", rows, ecosystem.species());
  const StatsFile back = readStatsCsv(folder / "stats.csv");
  EXPECT_EQ(back.species, std::vector<std::string>{"t"});
  ASSERT_EQ(back.rows.size(), 2u);
  EXPECT_EQ(back.rows[0].species, 0);
  EXPECT_EQ(back.rows[1].species, kAllSpecies);
  EXPECT_EQ(back.rows[1].planted, 12);
  EXPECT_EQ(back.rows[1].removed, 3);
  EXPECT_NEAR(back.rows[1].removedVolume_m3PerHa, 4.5, 1e-3);  // on one hectare
  EXPECT_NEAR(back.rows[0].basalArea_m2PerHa, rows[0].basalArea_m2PerHa, 1e-4);
  // An earlier version's file, without the plan's columns, reads with them as 0; a broken
  // one is refused at its line.
  test::writeFile(
      folder / "old.csv",
      "year,species,alive,born,died,mean_height_m,stems_per_ha,basal_area_m2_per_ha,"
      "qmd_cm,dominant_height_m,sdi,volume_m3_per_ha,cover_fraction,"
      "densest_hectare_basal_area_m2_per_ha\n3,all,5,1,0,2.0,100,3.5,21,14,80,20,0.4,5\n");
  EXPECT_EQ(readStatsCsv(folder / "old.csv").rows.at(0).planted, 0);
  test::writeFile(folder / "bad.csv", test::readFile(folder / "old.csv") +
                                          "4,all,5,1,0,nan,100,3.5,21,14,80,20,0.4,5\n");
  try {
    readStatsCsv(folder / "bad.csv");
    FAIL() << "a NaN was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 3);
  }
}

TEST(RunFormat, RunJsonReadsBackWhatWasWritten) {
  const RunPaths run{test::freshDirectory("run_format_json")};
  RunRecord r;
  r.version = "9.9";
  r.status = "failed";
  r.error = "disk full";
  r.scenarioFile = run.dir / "s.toml";
  r.scenarioName = "s";
  r.fingerprint = 0xfedcba9876543210ULL;
  r.scenarioText = "name = \"s\"\n";
  r.seed = 42;
  r.years = 60;
  r.lastYear = 17;
  r.threads = 2;
  r.counts = {{"beech", 10, 2, {}}};
  writeRunJson(run, r);
  const RunRecord back = readRunJson(run);
  EXPECT_EQ(back.version, r.version);
  EXPECT_EQ(back.status, r.status);
  EXPECT_EQ(back.error, r.error);
  EXPECT_EQ(back.scenarioFile, r.scenarioFile);
  EXPECT_EQ(back.scenarioName, r.scenarioName);
  EXPECT_EQ(back.fingerprint, r.fingerprint);
  EXPECT_EQ(back.scenarioText, r.scenarioText);
  EXPECT_EQ(back.seed, r.seed);
  EXPECT_EQ(back.years, r.years);
  EXPECT_EQ(back.lastYear, r.lastYear);
  EXPECT_EQ(back.threads, r.threads);
}

TEST(RunFormat, PathsListTheSnapshotsAndMapsThereAre) {
  const RunPaths run{test::freshDirectory("run_format_paths")};
  EXPECT_TRUE(run.snapshotYears().empty());
  std::filesystem::create_directories(run.treesFolder());
  std::filesystem::create_directories(run.mapsFolder());
  for (int year : {20, 5}) test::writeFile(run.snapshot(year, SnapshotFormat::Csv), "");
  for (int year : {100, 20}) test::writeFile(run.snapshot(year, SnapshotFormat::Binary), "");
  test::writeFile(run.treesFolder() / "notes.txt", "");
  test::writeFile(run.treesFolder() / "year_0030.txt", "");
  test::writeFile(run.map("moisture"), "");
  test::writeFile(run.mapsFolder() / "moisture.png", "");
  EXPECT_EQ(run.snapshot(5, SnapshotFormat::Csv).filename(), "year_0005.csv");
  EXPECT_EQ(run.snapshot(5, SnapshotFormat::Binary).filename(), "year_0005.bin");
  // Each year once, whichever formats it has; the binary snapshot where both are.
  EXPECT_EQ(run.snapshotYears(), (std::vector<int>{5, 20, 100}));
  EXPECT_EQ(run.existingSnapshot(5).filename(), "year_0005.csv");
  EXPECT_EQ(run.existingSnapshot(20).filename(), "year_0020.bin");
  EXPECT_EQ(run.existingSnapshot(100).filename(), "year_0100.bin");
  EXPECT_EQ(run.mapNames(), std::vector<std::string>{"moisture"});
}

}  // namespace
}  // namespace eco

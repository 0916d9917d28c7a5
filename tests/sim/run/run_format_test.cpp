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

const char* kHeader =
    "id,species,x_m,y_m,z_m,age,height_m,crown_radius_m,crown_base_m,dbh_m,vigor,variant_seed\n";

TEST(RunFormat, ReadsATreesFileAndNumbersSpeciesInOrderOfAppearance) {
  const auto file = test::freshDirectory("run_folder_csv") / "year_0010.csv";
  test::writeFile(file, std::string(kHeader) +
                            "7,pine,10.500,20.250,412.000,12,6.500,1.200,2.500,0.0800,0.900,123\n"
                            "9,beech,1.000,2.000,400.000,3,0.400,0.100,0.000,0.0000,1.000,5\n"
                            "11,pine,3.000,4.000,401.000,40,20.000,3.000,12.000,0.3000,0.500,"
                            "4294967295\n");
  const TreeSnapshot s = readTreesCsv(file);
  ASSERT_EQ(s.trees.size(), 3u);
  EXPECT_EQ(s.speciesNames, (std::vector<std::string>{"pine", "beech"}));
  EXPECT_EQ(s.trees[0].id, 7u);
  EXPECT_EQ(s.trees[0].species, 0);
  EXPECT_DOUBLE_EQ(s.trees[0].north_m, 20.25);
  EXPECT_FLOAT_EQ(s.trees[0].height_m, 6.5f);
  EXPECT_FLOAT_EQ(s.trees[0].crownBase_m, 2.5f);
  EXPECT_EQ(s.trees[1].species, 1);
  EXPECT_EQ(s.trees[2].species, 0);
  EXPECT_EQ(s.trees[2].variantSeed, 4294967295u);  // 32 bits, exact in a spreadsheet
  // A seed beyond 32 bits is not one ecoforest wrote.
  test::writeFile(file, std::string(kHeader) +
                            "7,pine,10.500,20.250,412.000,12,6.500,1.200,2.500,0.0800,0.900,"
                            "4294967296\n");
  EXPECT_THROW(readTreesCsv(file), InputError);
}

TEST(RunFormat, AMalformedTreesFileNamesTheLine) {
  const auto file = test::freshDirectory("run_folder_bad") / "trees.csv";
  test::writeFile(
      file, std::string(kHeader) +
                "1,pine,1,2,3,4,5,0.6,0.7,0.08,0.9,10\n2,pine,1,2,x,4,5,0.6,0.7,0.08,0.9,10\n");
  try {
    readTreesCsv(file);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 3);
  }
  test::writeFile(file, "id,name\n");
  EXPECT_THROW(readTreesCsv(file), InputError);
}

// A trees file is read back as untrusted input: each value a later command would turn into
// a NaN transform or a huge mesh is refused at its line.
TEST(RunFormat, TreesValuesOutOfRangeAreRefusedAtTheirLine) {
  const auto file = test::freshDirectory("run_folder_values") / "trees.csv";
  const std::string good = "7,pine,10.5,20.25,412,12,6.5,1.2,2.5,0.08,0.9,123";
  auto faultOf = [&](const std::string& row) {
    test::writeFile(file, std::string(kHeader) + good + "\n" + row + "\n");
    try {
      readTreesCsv(file);
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().line, 3) << row;
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(faultOf("8,pine,nan,20,412,12,6.5,1.2,2.5,0.08,0.9,1").find("numbers"),
            std::string::npos);
  EXPECT_NE(faultOf("8,pine,1,inf,412,12,6.5,1.2,2.5,0.08,0.9,1").find("numbers"),
            std::string::npos);
  EXPECT_NE(faultOf("8,pine,1,2,412,12,6.5,1.2,2.5,0.08,0.9,1,extra").find("numbers"),
            std::string::npos);
  EXPECT_NE(faultOf("8,pi/ne,1,2,412,12,6.5,1.2,2.5,0.08,0.9,1").find("not a species name"),
            std::string::npos);
  EXPECT_NE(faultOf("8,pine,1,2,412,-1,6.5,1.2,2.5,0.08,0.9,1").find("age -1"), std::string::npos);
  EXPECT_NE(faultOf("8,pine,1,2,412,12,1e30,1.2,2.5,0.08,0.9,1").find("height"), std::string::npos);
  EXPECT_NE(faultOf("8,pine,1,2,412,12,6.5,-1,2.5,0.08,0.9,1").find("crown radius"),
            std::string::npos);
  EXPECT_NE(faultOf("8,pine,1,2,412,12,6.5,1.2,9,0.08,0.9,1").find("crown base"),
            std::string::npos);
  EXPECT_NE(faultOf("8,pine,1,2,412,12,6.5,1.2,2.5,0.08,1.5,1").find("vigor"), std::string::npos);
  EXPECT_EQ(faultOf(good), "no error");
}

// A file of several megabytes is read in stretches side by side: the trees come back in
// the file's order, species numbered by first appearance across the stretches, empty lines
// skipped, and of two bad rows far apart the first is reported at its line.
TEST(RunFormat, ALongTreesFileReadsAsItsLinesInOrder) {
  const auto file = test::freshDirectory("run_format_long") / "trees.csv";
  constexpr int kRows = 60000;  // about 3 MB: a few stretches of a megabyte
  auto rowOf = [](int id, const char* species) {
    return std::to_string(id) + "," + species + ",1.5,2.5,400,7,6.5,1.2,2.5,0.08,0.9," +
           std::to_string(id % 1000) + "\n";
  };
  auto speciesOf = [](int id) { return id < 20000 ? "beech" : id < 45000 ? "pine" : "maple"; };
  std::string text = kHeader;
  std::vector<int> lineOf(kRows + 1);
  int line = 1;
  for (int id = 1; id <= kRows; ++id) {
    if (id % 7001 == 0) {
      text += "\n";  // an empty line between rows
      ++line;
    }
    text += rowOf(id, speciesOf(id));
    lineOf[id] = ++line;
  }
  ASSERT_GT(text.size(), std::size_t{2} << 20);
  test::writeFile(file, text);
  const TreeSnapshot s = readTreesCsv(file);
  ASSERT_EQ(s.trees.size(), static_cast<std::size_t>(kRows));
  EXPECT_EQ(s.speciesNames, (std::vector<std::string>{"beech", "pine", "maple"}));
  for (int id = 1; id <= kRows; ++id) {
    const TreeRow& tree = s.trees[static_cast<std::size_t>(id - 1)];
    ASSERT_EQ(tree.id, static_cast<std::uint64_t>(id));
    ASSERT_EQ(s.speciesNames[static_cast<std::size_t>(tree.species)], speciesOf(id));
    ASSERT_EQ(tree.variantSeed, static_cast<std::uint32_t>(id % 1000));
  }
  // Two bad rows, one near the end and one in the middle: the middle one is reported.
  auto bad = [&](int id) {
    const std::string good = rowOf(id, speciesOf(id));
    const std::size_t at = text.find("\n" + good) + 1;
    text.replace(at, good.size(), std::to_string(id) + ",pine,x\n");
  };
  bad(55000);
  bad(30000);
  test::writeFile(file, text);
  try {
    readTreesCsv(file);
    FAIL() << "a bad row was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, lineOf[30000]);
  }
}

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
  writeTreesCsv(folder / "trees.csv", ecosystem);
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

TEST_F(OneHectare, TheTreesReaderReadsWhatTheWriterWrote) {
  ecosystem.plant(0, 12.0, 33.0, 40);
  ecosystem.plant(0, 71.5, 8.25, 3);
  ecosystem.step();  // the sites are under a year's canopy
  const auto file = test::freshDirectory("run_format_trees") / "year_0001.csv";
  writeTreesCsv(file, ecosystem);
  const std::vector<PlantSite> sites = ecosystem.sitesOf(ecosystem.plants());
  const TreeSnapshot snapshot = readTreesCsv(file);
  const Plants& p = ecosystem.plants();
  ASSERT_EQ(snapshot.trees.size(), p.size());
  EXPECT_EQ(snapshot.speciesNames, std::vector<std::string>{"t"});
  for (std::size_t i = 0; i < p.size(); ++i) {
    const TreeRow& row = snapshot.trees[i];
    EXPECT_EQ(row.id, p.id[i]);
    EXPECT_NEAR(row.east_m, p.east_m[i], 5e-4);
    EXPECT_NEAR(row.north_m, p.north_m[i], 5e-4);
    EXPECT_EQ(row.age_years, p.age_years[i]);
    EXPECT_NEAR(row.height_m, p.height_m[i], 5e-4);
    EXPECT_EQ(row.variantSeed, ecosystem.variantSeedOf(p.id[i]));
    EXPECT_NEAR(row.ground_m, ecosystem.groundOf(p, i), 5e-4);
    EXPECT_NEAR(row.site.light.x, sites[i].light.x, 5e-3);
    EXPECT_NEAR(row.site.light.y, sites[i].light.y, 5e-3);
    EXPECT_NEAR(row.site.wind.x, sites[i].wind.x, 5e-3);
    EXPECT_NEAR(row.site.wind.y, sites[i].wind.y, 5e-3);
  }
}

// The site columns (light and wind toward east and north) read back; a file of an earlier
// version without them reads as unshaped trees (the tests above); a direction longer than 1
// is refused at its line.
TEST(RunFormat, TheSiteColumnsReadBackAndAreChecked) {
  const auto file = test::freshDirectory("run_format_site") / "year_0010.csv";
  const std::string header = std::string(kTreesCsvHeader) + "\n";
  test::writeFile(file, header +
                            "7,pine,10.5,20.25,412,12,6.5,1.2,2.5,0.08,0.9,123,"
                            "0.60,-0.25,0.00,0.71\n");
  const TreeSnapshot s = readTreesCsv(file);
  ASSERT_EQ(s.trees.size(), 1u);
  EXPECT_FLOAT_EQ(s.trees[0].site.light.x, 0.6f);
  EXPECT_FLOAT_EQ(s.trees[0].site.light.y, -0.25f);
  EXPECT_FLOAT_EQ(s.trees[0].site.wind.y, 0.71f);
  for (const char* row : {"7,pine,10.5,20.25,412,12,6.5,1.2,2.5,0.08,0.9,123,0.9,0.9,0,0",
                          "7,pine,10.5,20.25,412,12,6.5,1.2,2.5,0.08,0.9,123,0,0,1.2,0",
                          "7,pine,10.5,20.25,412,12,6.5,1.2,2.5,0.08,0.9,123,0,0,0",
                          "7,pine,10.5,20.25,412,12,6.5,1.2,2.5,0.08,0.9,123"}) {
    test::writeFile(file, header + row + "\n");
    try {
      readTreesCsv(file);
      ADD_FAILURE() << row;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().line, 2) << row;
    }
  }
}

TEST_F(OneHectare, ALargeSnapshotIsWrittenInBatchesInOrder) {
  // More rows than one batch of formatted chunks (64 x 16,384), so batches meet.
  const std::size_t n = 64 * 16384 + 1000;
  Plants p;
  p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    p.id[i] = i + 1;
    p.age_years[i] = static_cast<std::int32_t>(i % 97);
  }
  const auto file = test::freshDirectory("run_format_batches") / "year_0001.csv";
  writeTreesCsv(file, ecosystem, p);
  const TreeSnapshot snapshot = readTreesCsv(file);
  ASSERT_EQ(snapshot.trees.size(), n);
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_EQ(snapshot.trees[i].id, i + 1);
    ASSERT_EQ(snapshot.trees[i].age_years, static_cast<int>(i % 97));
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
  for (int year : {20, 5, 100}) test::writeFile(run.snapshot(year), "");
  test::writeFile(run.treesFolder() / "notes.txt", "");
  test::writeFile(run.map("moisture"), "");
  test::writeFile(run.mapsFolder() / "moisture.png", "");
  EXPECT_EQ(run.snapshot(5).filename(), "year_0005.csv");
  EXPECT_EQ(run.snapshotYears(), (std::vector<int>{5, 20, 100}));
  EXPECT_EQ(run.mapNames(), std::vector<std::string>{"moisture"});
}

}  // namespace
}  // namespace eco

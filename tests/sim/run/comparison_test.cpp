#include "sim/run/comparison.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

constexpr const char* kHeader =
    "year,species,alive,born,died,mean_height_m,stems_per_ha,basal_area_m2_per_ha,qmd_cm,"
    "dominant_height_m,sdi,volume_m3_per_ha,cover_fraction,densest_hectare_basal_area_m2_per_ha,"
    "planted,died_after_planting,removed,removed_volume_m3_per_ha\n";

// A run folder with a stats.csv of `years` years: beech holds 3/4 of the basal area, and
// every year 10 trees are planted and 2.5 m3/ha removed.
std::filesystem::path runWith(const std::string& name, int years) {
  const auto dir = test::freshDirectory(name);
  std::string csv = kHeader;
  for (int y = 1; y <= years; ++y) {
    const double ba = 0.5 * y;
    csv += fmt::format("{},beech,10,0,0,1,100,{},20,5,100,10,0.5,0,7,0,1,2.0\n", y, 0.75 * ba);
    csv += fmt::format("{},pine,10,0,0,1,100,{},20,5,100,10,0.5,0,3,0,1,0.5\n", y, 0.25 * ba);
    csv += fmt::format("{},all,20,0,0,2,{},{},20,{},100,20,0.6,0,10,0,2,2.5\n", y, 10 * y, ba, y);
  }
  test::writeFile(dir / "stats.csv", csv);
  return dir;
}

TEST(Comparison, ARunsYearsCarryItsMeasuresAndWhatItsPlanDidSoFar) {
  const ComparedRun run = readComparedRun(runWith("comparison_run", 40), "a");
  ASSERT_EQ(run.lastYear(), 40);
  const StandYear& y = run.at(30);
  EXPECT_DOUBLE_EQ(y.stand.basalArea_m2PerHa, 15.0);
  EXPECT_DOUBLE_EQ(y.stand.stemsPerHa, 300.0);
  EXPECT_DOUBLE_EQ(y.stand.dominantHeight_m, 30.0);
  EXPECT_DOUBLE_EQ(y.removedVolumeSoFar_m3PerHa, 75.0);  // 30 years of 2.5
  EXPECT_EQ(y.plantedSoFar, 300);
  EXPECT_DOUBLE_EQ(y.basalAreaShare.at("beech"), 0.75);
  EXPECT_DOUBLE_EQ(y.basalAreaShare.at("pine"), 0.25);
  EXPECT_THROW(run.at(41), InputError);
}

TEST(Comparison, DefaultYearsAreThoseOf30_60_100EveryRunReaches) {
  const std::vector<ComparedRun> runs{readComparedRun(runWith("comparison_a", 80), "a"),
                                      readComparedRun(runWith("comparison_b", 120), "b")};
  EXPECT_EQ(comparisonYears(runs, {}), (std::vector<int>{30, 60}));
  EXPECT_EQ(comparisonYears(runs, {50, 10, 50}), (std::vector<int>{10, 50}));
  EXPECT_THROW(comparisonYears(runs, {100}), InputError);  // a does not reach it
  const std::vector<ComparedRun> young{readComparedRun(runWith("comparison_c", 20), "c"), runs[0]};
  EXPECT_EQ(comparisonYears(young, {}), std::vector<int>{20});
}

TEST(Comparison, TheTablesHoldARowPerRunAndYear) {
  const std::vector<ComparedRun> runs{readComparedRun(runWith("comparison_t1", 60), "natural"),
                                      readComparedRun(runWith("comparison_t2", 60), "planted")};
  const std::string csv = comparisonCsv(runs, {30, 60});
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "run,year,basal_area_m2_per_ha,stems_per_ha,mean_height_m,dominant_height_m,"
            "cover_fraction,volume_m3_per_ha,removed_volume_m3_per_ha,planted,plants,"
            "share_beech,share_pine");
  EXPECT_NE(csv.find("\nnatural,30,15.00,300.0,2.00,30.00,0.6000,20.0,75.0,300,20,0.7500,0.2500\n"),
            std::string::npos)
      << csv;
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
  const std::string md = comparisonMarkdown(runs, {30, 60});
  EXPECT_NE(md.find("## Year 60"), std::string::npos);
  EXPECT_NE(md.find("| planted | 30.0 | 600 |"), std::string::npos) << md;
}

TEST(Comparison, ABrokenStatsFileIsAnErrorAtItsLine) {
  const auto dir = runWith("comparison_broken", 3);
  test::writeFile(dir / "stats.csv", test::readFile(dir / "stats.csv") + "4,all,1,2\n");
  try {
    readComparedRun(dir, "x");
    FAIL() << "a short line was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 11);
  }
  test::writeFile(dir / "stats.csv",
                  std::string(kHeader) + "2,all,20,0,0,2,1,1,20,1,1,1,0.6,0,0,0,0,0\n");
  EXPECT_THROW(readComparedRun(dir, "x"), InputError);  // year 1 is missing
}

}  // namespace
}  // namespace eco

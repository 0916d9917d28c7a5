// Runs `ecoforest stand` as a user would.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "app_support.hpp"
#include "test_scenarios.hpp"

namespace {

using eco::test::CommandResult;
using eco::test::ecoforest;

// The planted plot (test_scenarios.hpp) grown once for every test here.
const std::filesystem::path& plotRun() {
  static const std::filesystem::path run = [] {
    const auto dir = eco::test::freshDirectory("app_stand");
    eco::test::writeFile(dir / "plot.toml", eco::test::plantedPlotScenario(ECOFOREST_DATA_DIR));
    CommandResult r = ecoforest(
        fmt::format("run {} --out {}", (dir / "plot.toml").string(), (dir / "run").string()));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return dir / "run";
  }();
  return run;
}

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
  return fields;
}

TEST(StandCommand, PrintsAndWritesTheStandTableThatAddsUpToStatsCsv) {
  const auto out = eco::test::freshDirectory("app_stand_out") / "stand.csv";
  CommandResult r = ecoforest(fmt::format("stand {} --out {}", plotRun().string(), out.string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("year 40, 0.20 ha"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("pine"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("total"), std::string::npos) << r.output;

  // The stand's classes add up to the year's stems and basal area in stats.csv.
  std::istringstream csv(eco::test::readFile(out));
  std::string line;
  std::getline(csv, line);
  ASSERT_EQ(line.rfind("year,species,dbh_from_cm,dbh_to_cm,stems_per_ha", 0), 0u);
  double stems = 0.0, basalArea = 0.0;
  int standClasses = 0;
  while (std::getline(csv, line)) {
    const std::vector<std::string> f = splitCsv(line);
    ASSERT_EQ(f.size(), 9u) << line;
    EXPECT_EQ(f[0], "40");
    if (f[1] != "all") continue;
    ++standClasses;
    stems += std::stod(f[4]);
    basalArea += std::stod(f[5]);
  }
  EXPECT_GE(standClasses, 2);  // pines of 40 years on 2 m reach past 15 cm
  std::istringstream stats(eco::test::readFile(plotRun() / "stats.csv"));
  while (std::getline(stats, line))
    if (line.rfind("40,all,", 0) == 0) break;
  const std::vector<std::string> f = splitCsv(line);
  ASSERT_GT(f.size(), 7u) << line;
  EXPECT_NEAR(stems, std::stod(f[6]), 0.05 + 0.005 * standClasses);
  EXPECT_NEAR(basalArea, std::stod(f[7]), 1e-4 + 5e-5 * standClasses);
}

TEST(StandCommand, TakesAnEarlierYearAndAClassWidth) {
  CommandResult r =
      ecoforest(fmt::format("stand {} --year 20 --class-width 10", plotRun().string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("year 20"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("classes of 10 cm"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("10-20"), std::string::npos) << r.output;
}

// Several years, or every snapshot year: a table each, and the CSV's lines of each year.
TEST(StandCommand, TalliesSeveralYearsIntoOneCsv) {
  const auto folder = eco::test::freshDirectory("app_stand_years");
  for (const char* years : {"--year 20,40", "--all-years"}) {
    const auto out = folder / "years.csv";
    CommandResult r =
        ecoforest(fmt::format("stand {} {} --out {}", plotRun().string(), years, out.string()));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_LT(r.output.find("year 20,"), r.output.find("year 40,")) << r.output;
    std::istringstream csv(eco::test::readFile(out));
    std::string line;
    std::getline(csv, line);  // the header
    std::set<std::string> seen;
    while (std::getline(csv, line)) seen.insert(splitCsv(line).at(0));
    EXPECT_EQ(seen, (std::set<std::string>{"20", "40"})) << years;
  }
  CommandResult both = ecoforest(fmt::format("stand {} --year 20 --all-years", plotRun().string()));
  EXPECT_EQ(both.exitCode, 2) << both.output;
  CommandResult missing = ecoforest(fmt::format("stand {} --year 20,30", plotRun().string()));
  EXPECT_EQ(missing.exitCode, 2) << missing.output;
  EXPECT_NE(missing.output.find("year 30"), std::string::npos) << missing.output;
}

TEST(StandCommand, RefusesBadInputWithExitTwo) {
  const std::string run = plotRun().string();
  CommandResult noYear = ecoforest(fmt::format("stand {} --year 7", run));
  EXPECT_EQ(noYear.exitCode, 2) << noYear.output;
  EXPECT_NE(noYear.output.find("20, 40"), std::string::npos) << noYear.output;
  CommandResult width = ecoforest(fmt::format("stand {} --class-width 0", run));
  EXPECT_EQ(width.exitCode, 2) << width.output;
  CommandResult notARun = ecoforest("stand valley");
  EXPECT_EQ(notARun.exitCode, 2) << notARun.output;
  const auto missing = eco::test::freshDirectory("app_stand_missing") / "no" / "t.csv";
  CommandResult noFolder = ecoforest(fmt::format("stand {} --out {}", run, missing.string()));
  EXPECT_EQ(noFolder.exitCode, 2) << noFolder.output;
  EXPECT_FALSE(std::filesystem::exists(missing.parent_path()));
}

// A region given as a plan gives it: its trees, per hectare of its cells.
TEST(StandCommand, TalliesTheTreesWithinARegion) {
  const std::string run = plotRun().string();
  CommandResult r = ecoforest(fmt::format(
      "stand {} --region 'polygon = [[-10, -10], [17.5, -10], [17.5, 50], [-10, 50]]'", run));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("year 40, 0.09 ha within the region"), std::string::npos) << r.output;
  for (const char* bad : {"'polygon = [[0, 0], [10, 0]]'",
                          "'polygon = [[100, 100], [200, 100], "
                          "[200, 200]]'",
                          "'colour = 3'", "'buffer_m = 3'", "'polygon = [[0, 0]'"}) {
    CommandResult refused = ecoforest(fmt::format("stand {} --region {}", run, bad));
    EXPECT_EQ(refused.exitCode, 2) << bad << refused.output;
    EXPECT_NE(refused.output.find("--region:"), std::string::npos) << refused.output;
  }
}

TEST(StandCommand, RefusesASnapshotOfSpeciesTheScenarioDoesNotHave) {
  // The run's folder with its last snapshot as CSV, in which the pines became oaks.
  const auto copy = eco::test::freshDirectory("app_stand_oaks") / "run";
  std::filesystem::copy(plotRun(), copy, std::filesystem::copy_options::recursive);
  const auto csv = copy / "trees" / "year_0040.csv";
  CommandResult exported =
      ecoforest(fmt::format("export {} --out {}", copy.string(), csv.string()));
  ASSERT_EQ(exported.exitCode, 0) << exported.output;
  std::filesystem::remove(copy / "trees" / "year_0040.bin");
  std::string text = eco::test::readFile(csv);
  for (std::size_t at = text.find(",pine,"); at != std::string::npos; at = text.find(",pine,", at))
    text.replace(at, 6, ",oak,");
  eco::test::writeFile(csv, text);
  CommandResult r = ecoforest("stand " + copy.string());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("year_0040.csv"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("'oak'"), std::string::npos) << r.output;
}

}  // namespace

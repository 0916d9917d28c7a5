#include "sim/run/validation.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

const char* kTable =
    "# a made-up table\n"
    "age,stems_per_ha,basal_area_m2_per_ha,qmd_cm\n"
    "60,400,28.27,30.0\n"
    "120,131,28.27,52.4\n";

std::string errorOf(const std::string& text) {
  const auto file = test::freshDirectory("yield_table_bad") / "t.csv";
  test::writeFile(file, text);
  try {
    readYieldTable(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Validation, ReadsAYieldTable) {
  const auto file = test::freshDirectory("yield_table") / "t.csv";
  test::writeFile(file, kTable);
  const std::vector<YieldTableRow> rows = readYieldTable(file);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].age_years, 120);
  EXPECT_DOUBLE_EQ(rows[1].stemsPerHa, 131.0);
  EXPECT_DOUBLE_EQ(rows[1].qmd_cm, 52.4);
}

TEST(Validation, ABadYieldTableNamesItsLine) {
  EXPECT_NE(errorOf("age,n\n").find("t.csv:1: expected the header"), std::string::npos);
  EXPECT_NE(
      errorOf(std::string(kTable) + "130,x,1,1\n").find("t.csv:5: expected a positive number"),
      std::string::npos);
  EXPECT_NE(errorOf(std::string(kTable) + "110,1,1,1\n").find("t.csv:5: ages must ascend"),
            std::string::npos);
  EXPECT_NE(errorOf(std::string(kTable) + "130,1,1\n").find("t.csv:5: expected 4"),
            std::string::npos);
  // An age beyond int's range (the fuzzer's find: converting it was undefined).
  EXPECT_NE(errorOf(std::string(kTable) + "4.4e82,1,1,1\n").find("t.csv:5: the age must be whole"),
            std::string::npos);
  EXPECT_NE(errorOf("# nothing\nage,stems_per_ha,basal_area_m2_per_ha,qmd_cm\n").find("no rows"),
            std::string::npos);
}

TEST(Validation, TheSelfThinningSlopeOfReinekesLine) {
  std::vector<StandMeasures> stands;
  for (double qmd : {20.0, 30.0, 45.0}) {
    StandMeasures m;
    m.qmd_cm = qmd;
    m.stemsPerHa = 5e5 * std::pow(qmd, -1.605);
    stands.push_back(m);
  }
  EXPECT_NEAR(selfThinningSlope(stands), -1.605, 1e-12);
  EXPECT_TRUE(std::isnan(selfThinningSlope({stands[0]})));
}

// A run folder written by hand: 85 m x 85 m (0.7225 ha), a planted beech cohort (age = year) among
// ingrowth and another species, which the comparison leaves out.
struct HandMadeRun {
  std::filesystem::path dir = test::freshDirectory("validation_run");
  RunFolder run;

  HandMadeRun(const std::string& tableText, const std::string& checkedAges) {
    test::writeFile(dir / "table.csv", tableText);
    test::writeFile(dir / "scenario.toml", fmt::format(R"(name = "plot"
[terrain]
cell_size_m = 5
[terrain.generate]
size = 17
relief_m = 0
[[planting]]
species = "beech"
[validation]
yield_table = "table.csv"
species = "beech"
checked_ages = {}
)",
                                                       checkedAges));
    std::filesystem::create_directories(dir / "trees");
    run.dir = dir;
    run.scenario = loadScenario(dir / "scenario.toml");
    // Year 60: 289 cohort trees of 30 cm (400 per ha); year 120: 95 of 52.4 cm (131 per ha).
    for (auto [year, count, dbh] : {std::tuple{60, 289, 0.30}, {120, 95, 0.524}}) {
      std::string rows = std::string(kTreesCsvHeaderWithoutSite) + "\n";
      for (int i = 0; i < count; ++i)
        rows += fmt::format("{},beech,{},{},0,{},30,4,15,{},0.5,1\n", i + 1, i % 100, i / 100, year,
                            dbh);
      rows += fmt::format("9001,beech,5,5,0,{},30,4,15,0.6,0.5,1\n", year - 20);  // ingrowth
      rows += fmt::format("9002,pine,5,5,0,{},30,4,15,0.6,0.5,1\n", year);        // not beech
      test::writeFile(dir / "trees" / fmt::format("year_{:04d}.csv", year), rows);
      run.snapshotYears.push_back(year);
    }
  }
};

TEST(Validation, ComparesThePlantedCohortWithTheTable) {
  HandMadeRun made(kTable, "[60, 120]");
  const ValidationReport report = validateRun(made.run);
  ASSERT_EQ(report.ages.size(), 2u);
  const ValidationAge& young = report.ages[0];
  EXPECT_NEAR(young.simulated.stemsPerHa, 400.0, 1e-9);
  EXPECT_NEAR(young.simulated.qmd_cm, 30.0, 1e-4);  // diameters are floats
  EXPECT_NEAR(young.simulated.basalArea_m2PerHa, 400 * std::numbers::pi / 4 * 0.09, 1e-4);
  EXPECT_LT(young.worstError(), 0.01);
  EXPECT_TRUE(young.checked);
  // ln(131 / 400) / ln(52.4 / 30): Reineke's slope.
  EXPECT_NEAR(report.simulatedSlope, std::log(95.0 / 289.0) / std::log(0.524 / 0.30), 1e-5);
  EXPECT_NEAR(report.tableSlope, std::log(131.0 / 400.0) / std::log(52.4 / 30.0), 1e-12);
  EXPECT_TRUE(report.passed());
}

TEST(Validation, FailsBeyondTheToleranceAndForAMissingSnapshot) {
  // A table with 30 % more stems at 60 years.
  HandMadeRun denser(
      "age,stems_per_ha,basal_area_m2_per_ha,qmd_cm\n60,520,28.27,30.0\n"
      "120,131,28.27,52.4\n",
      "[60]");
  const ValidationReport report = validateRun(denser.run);
  EXPECT_NEAR(report.ages[0].stemsError(), 400.0 / 520.0 - 1.0, 1e-9);
  EXPECT_FALSE(report.agesPassed());
  EXPECT_TRUE(report.slopePassed() ==
              (report.simulatedSlope >= -2.0 && report.simulatedSlope <= -1.3));
  HandMadeRun late(std::string(kTable) + "140,100,30,60\n", "[60, 140]");
  EXPECT_THROW(validateRun(late.run), InputError);  // no snapshot of year 140
  HandMadeRun unknownAge(kTable, "[70]");
  EXPECT_THROW(validateRun(unknownAge.run), InputError);
}

}  // namespace
}  // namespace eco
